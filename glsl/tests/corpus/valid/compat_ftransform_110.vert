#version 110
varying vec3 normal;
varying vec3 eyePos;
attribute float weight;
uniform float scale;

void main()
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    eyePos = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_FrontColor = gl_Color * weight;
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_MultiTexCoord1 * scale;
    gl_Position = ftransform();
}
