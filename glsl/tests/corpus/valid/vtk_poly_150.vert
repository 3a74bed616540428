//VTK::System::Dec
#version 150
#ifdef GL_ES
precision highp float;
#endif

/*=========================================================================
  Program:   Visualization Toolkit
  Module:    vtkPolyDataVS.glsl
=========================================================================*/

in vec4 vertexMC;
in vec3 normalMC;
in vec2 tcoordMC;
in vec4 scalarColor;

uniform mat3 normalMatrix;
uniform mat4 MCDCMatrix;
uniform mat4 MCVCMatrix;

out vec3 normalVCVSOutput;
out vec4 vertexVCVSOutput;
out vec2 tcoordVCVSOutput;
out vec4 vertexColorVSOutput;

void main()
{
  vertexColorVSOutput = scalarColor;
  normalVCVSOutput = normalMatrix * normalMC;
  tcoordVCVSOutput = tcoordMC;
  vertexVCVSOutput = MCVCMatrix * vertexMC;
  gl_Position = MCDCMatrix * vertexMC;
}
