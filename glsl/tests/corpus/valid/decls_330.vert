#version 330 core
precision highp float;
precision mediump int;
layout(location = 0) in highp vec4 pos;
layout(location = 3) in vec2 uvs[2];
uniform struct Light { vec3 dir; vec3 col; } light;
struct Mat { vec4 c; float s[2]; };
uniform Mat mats[3];
const float weights[3] = float[3](0.2, 0.3, 0.5);
const vec2 table[] = vec2[](vec2(1.0), vec2(2.0));
out Data { smooth vec2 uv; flat int idx; noperspective float z; } outData;
out float single, pair[2];
invariant out vec4 inv;
layout(std140) uniform;
layout(shared, column_major) uniform Globals { mat4 vp; layout(row_major) mat4 w; };
float[3] arrayReturning(float a[3]) { return a; }
void f(const in float a, out vec2 b, inout int c[2]);
int g(void);
int g() { return 0; }

void main()
{
    float tmp[3] = arrayReturning(weights);
    outData.uv = uvs[1] + table[1];
    outData.idx = gl_VertexID;
    outData.z = tmp[2] * mats[2].s[1];
    single = weights[0];
    pair[0] = pair[1] = 0.0;
    inv = vec4(light.dir, 1.0);
    gl_Position = vp * w * pos;
}
