#version 150 core
uniform sampler3D in_volume;
uniform sampler2D in_colorTransferFunc;
uniform sampler2D in_opacityTransferFunc;
uniform sampler2DRect depthTex;
uniform vec3 in_cellStep;
uniform float in_sampleDistance;
uniform vec2 in_scalarsRange;
uniform int in_noOfComponents;
in vec3 ip_textureCoords;
out vec4 fragColor;

vec4 computeColor(vec4 scalar, float opacity)
{
  return vec4(texture(in_colorTransferFunc, vec2(scalar.w, 0.0)).xyz, opacity);
}

float computeOpacity(vec4 scalar)
{
  return texture(in_opacityTransferFunc, vec2(scalar.w, 0)).r;
}

void main()
{
  vec3 g_dataPos = ip_textureCoords;
  vec3 g_dirStep = in_cellStep * in_sampleDistance;
  vec4 g_fragColor = vec4(0.0);
  bool g_exit = false;
  const float g_opacityThreshold = 1.0 - 1.0 / 255.0;
  int curSample = 0;
  while (!g_exit)
  {
    vec4 scalar = texture(in_volume, g_dataPos);
    scalar.r = (scalar.r - in_scalarsRange[0]) / (in_scalarsRange[1] - in_scalarsRange[0]);
    scalar = vec4(scalar.r, scalar.r, scalar.r, scalar.r);
    vec4 g_srcColor = computeColor(scalar, computeOpacity(scalar));
    g_srcColor.rgb *= g_srcColor.a;
    g_fragColor = (1.0f - g_fragColor.a) * g_srcColor + g_fragColor;
    g_dataPos += g_dirStep;
    if (any(greaterThan(g_dataPos, vec3(1.0))) || any(lessThan(g_dataPos, vec3(0.0))))
      g_exit = true;
    if (g_fragColor.a > g_opacityThreshold)
      g_exit = true;
    if (++curSample > 1000) break;
  }
  fragColor = g_fragColor;
}
