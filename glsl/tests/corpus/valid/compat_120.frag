#version 120
varying mat3 tbn;
varying vec2 uv;
uniform sampler2D normalMap;
uniform sampler2DShadow shadow;
uniform samplerCube env;
uniform vec4 shadowCoord;
centroid varying vec4 dummy;

void main()
{
    vec3 n = tbn * (texture2D(normalMap, uv).xyz * 2.0 - 1.0);
    float s = shadow2DProj(shadow, shadowCoord).r;
    vec4 e = textureCube(env, reflect(vec3(0.0, 0.0, -1.0), n));
    gl_FragData[0] = vec4(n * 0.5 + 0.5, 1.0) * s;
    gl_FragData[1] = e;
    gl_FragDepth = gl_FragCoord.z;
}
