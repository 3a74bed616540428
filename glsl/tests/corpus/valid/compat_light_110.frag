varying vec3 normal;
varying vec3 eyePos;
uniform sampler2D tex;
uniform sampler2D tex2;
uniform bool useFog;

vec4 light(in int i, in vec3 n, inout vec4 spec)
{
    vec3 L = normalize(gl_LightSource[i].position.xyz - eyePos);
    vec3 E = normalize(-eyePos);
    vec3 R = normalize(-reflect(L, n));
    vec4 amb = gl_FrontLightProduct[i].ambient;
    vec4 diff = gl_FrontLightProduct[i].diffuse * max(dot(n, L), 0.0);
    spec += gl_FrontLightProduct[i].specular * pow(max(dot(R, E), 0.0), 0.3 * gl_FrontMaterial.shininess);
    return amb + diff;
}

void main()
{
    vec3 n = normalize(normal);
    vec4 spec = vec4(0.0);
    vec4 c = gl_FrontLightModelProduct.sceneColor + light(0, n, spec) + light(1, n, spec);
    c *= texture2D(tex, gl_TexCoord[0].st) * texture2D(tex2, gl_TexCoord[1].xy);
    c += spec;
    if (useFog) {
        float f = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);
        c = mix(gl_Fog.color, c, f);
    }
    gl_FragColor = c * gl_Color;
}
