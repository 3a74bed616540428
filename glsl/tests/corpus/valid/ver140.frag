#version 140
#extension GL_ARB_explicit_attrib_location : require
in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2DRect rect;
uniform isampler2DRect irect;
uniform samplerBuffer buf;
layout(std140) uniform Params {
    vec4 tint;
    float gain;
    int mode;
};

void main()
{
    vec4 a = texture(rect, uv * 64.0);
    ivec4 b = texture(irect, uv);
    vec4 c = texelFetch(buf, int(uv.x * 100.0));
    color = (a + vec4(b) + c) * tint * gain;
}
