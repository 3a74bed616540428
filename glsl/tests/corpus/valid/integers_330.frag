#version 330
flat in ivec4 ids;
flat in uint mask;
noperspective in vec2 uv;
centroid in vec3 normal;
layout(location = 0) out vec4 color;
layout(location = 1) out uvec4 extra;
uniform usampler2D lut;
uniform isampler3D vol;

uint hash(uint x)
{
    x ^= x >> 16u;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

void main()
{
    int a = ids.x % 7, b = ids.y << 2, c = ~ids.z & 0xff, d = ids.w | 010;
    uint h = hash(mask ^ uint(a + b));
    switch (a) {
    case 0:
        color = vec4(1.0, 0.0, 0.0, 1.0);
        break;
    case 1:
    case 2:
        color = vec4(float(b) / 255.0);
        break;
    default:
        color = vec4(uv, 0.0, 1.0);
    }
    uvec4 t = texelFetch(lut, ivec2(c, d), 0);
    ivec4 v = texture(vol, normal);
    extra = t + uvec4(h) + uvec4(v);
    if ((h & 1u) == 0u && !(a > 3 ^^ b < 2))
        discard;
}
