#version 130
flat in uint vMaterial;
noperspective in float vDepth;
in vec2 vUv;
out vec4 color;
uniform sampler2DArray layers;
uniform usampler2D ids;
uniform lowp float alpha;
precision mediump float;

void main()
{
    uvec4 id = texelFetch(ids, ivec2(gl_FragCoord.xy), 0);
    vec4 c = textureLod(layers, vec3(vUv, float(vMaterial)), 0.0);
    c += textureGrad(layers, vec3(vUv, 0.0), dFdx(vUv), dFdy(vUv));
    c += textureOffset(layers, vec3(vUv, 1.0), ivec2(1, -1));
    ivec3 sz = textureSize(layers, 0);
    color = vec4(c.rgb * float(id.r % 3u), alpha) + vec4(float(sz.x), vDepth, 0.0, 0.0) * 0.0;
}
