#version 150
#ifdef GL_ES
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
precision highp sampler2D;
precision highp sampler3D;
#else
precision mediump float;
#endif
#endif
#define varying in
#define texelFetchBuffer texelFetch
#define texture1D texture
#define texture2D texture
#define texture3D texture
out vec4 fragOutput0;

uniform int PrimitiveIDOffset;
uniform float opacityUniform;
uniform vec3 ambientColorUniform;
uniform vec3 diffuseColorUniform;
uniform float specularPowerUniform;
uniform vec3 specularColorUniform;
uniform int numberOfLights;
uniform vec3 lightColor[6];
uniform vec3 lightDirectionVC[6];
uniform vec3 lightHalfAngleVC[6];
uniform sampler2D texture_0;

varying vec3 normalVCVSOutput;
varying vec4 vertexVCVSOutput;
varying vec2 tcoordVCVSOutput;
varying vec4 vertexColorVSOutput;

void main()
{
  vec3 ambientColor = ambientColorUniform;
  vec3 diffuseColor = diffuseColorUniform * vertexColorVSOutput.rgb;
  float opacity = opacityUniform * vertexColorVSOutput.a;
  vec3 normalVCVSOutput = normalize(normalVCVSOutput);
  if (gl_FrontFacing == false) { normalVCVSOutput = -normalVCVSOutput; }
  vec3 diffuse = vec3(0,0,0);
  vec3 specular = vec3(0,0,0);
  float df;
  float sf;
  for (int lightNum = 0; lightNum < numberOfLights; lightNum++)
  {
    df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC[lightNum]));
    diffuse += (df * lightColor[lightNum]);
    sf = sign(df)*pow(max(0.0, dot( lightHalfAngleVC[lightNum], normalVCVSOutput)), specularPowerUniform);
    specular += (sf * lightColor[lightNum]);
  }
  diffuse = diffuse * diffuseColor;
  specular = specular * specularColorUniform;
  vec4 tcolor = texture2D(texture_0, tcoordVCVSOutput);
  fragOutput0 = vec4(ambientColor + diffuse + specular, opacity) * tcolor;
  if (fragOutput0.a <= 0.0)
    {
    discard;
    }
}
