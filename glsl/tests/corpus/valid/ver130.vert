#version 130
in vec3 position;
in uint materialId;
flat out uint vMaterial;
noperspective out float vDepth;
out vec2 vUv;
uniform mat4 mvp;

void main()
{
    vMaterial = materialId;
    vUv = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec4 p = mvp * vec4(position, 1.0);
    vDepth = p.z / p.w;
    gl_Position = p;
    gl_ClipDistance[0] = dot(p, vec4(0.0, 0.0, 1.0, 1.0));
}
