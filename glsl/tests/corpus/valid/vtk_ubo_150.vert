#version 150
layout(std140) uniform Transform {
  mat4 modelView;
  mat4 projection;
  mat3 normalMatrix;
} xform;
layout(std140, row_major) uniform Lights
{
  vec4 position[4];
  vec4 color[4];
  int count;
};
in vec3 vertexMC;
in vec3 normalMC;
smooth out vec3 normalVC;
flat out int lightCount;
out Varyings {
  vec3 posVC;
  float depth;
} vOut;
invariant gl_Position;

void main()
{
  vec4 p = xform.modelView * vec4(vertexMC, 1.0);
  vOut.posVC = p.xyz;
  vOut.depth = -p.z;
  normalVC = normalize(xform.normalMatrix * normalMC);
  lightCount = count;
  gl_Position = xform.projection * p;
}
