#version 120
attribute vec4 position;
attribute vec3 tangent;
varying mat3 tbn;
varying vec2 uv;
uniform mat4 mvp;
uniform mat3x4 bones[8];
invariant varying vec4 dummy;
const vec3 up = vec3(0.0, 1.0, 0.0);

void main()
{
    vec3 b = cross(gl_Normal, tangent);
    tbn = mat3(tangent, b, gl_Normal);
    float w[4] = float[4](0.25, 0.25, 0.25, 0.25);
    vec4 p = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        p += vec4(position * bones[i], 1.0) * w[i];
    uv = gl_MultiTexCoord0.xy;
    dummy = vec4(up, w.length());
    gl_Position = mvp * p;
    gl_PointSize = 2.0f;
}
