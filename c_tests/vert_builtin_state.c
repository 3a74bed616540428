/* vert_builtin_state: a vertex shader reading the built-in state uniforms of GLSL 1.10
 * (gl_LightSource[], gl_FrontMaterial, gl_BackMaterial, gl_LightModel, the light and
 * light-model products, gl_Fog, gl_DepthRange, gl_ClipPlane[], gl_Point,
 * gl_TextureEnvColor[], the texgen planes), and fragment shaders reading them
 * (material, light model, fog, depth range; light 0 and its products): classic per-vertex
 * lighting written in GLSL (a directional light with the half vector, a positional
 * spot light with attenuation), against values Mesa fetches from the GL state. Lights
 * and materials change between draws; the light positions are given under a rotated
 * modelview. The exponents scale linear terms here: with `pow` (gallivm's is matched
 * within stated ulps only, tests/shader_mesa.rs), or a cube in its place, one pixel in
 * 16384 is off by one. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include "vert_program.h"

static const char *VS_LIGHT =
    "void main() {\n"
    "  vec3 n = normalize(gl_NormalMatrix * gl_Normal);\n"
    "  vec4 e = gl_ModelViewMatrix * gl_Vertex;\n"
    "  vec4 c = gl_FrontLightModelProduct.sceneColor;\n"
    "  /* light 0: directional, Blinn-Phong with the half vector */\n"
    "  vec3 l0 = normalize(gl_LightSource[0].position.xyz);\n"
    "  float d0 = max(dot(n, l0), 0.0);\n"
    "  c += gl_FrontLightProduct[0].ambient + gl_FrontLightProduct[0].diffuse * d0;\n"
    "  if (d0 > 0.0) {\n"
    "    float s = max(dot(n, gl_LightSource[0].halfVector.xyz), 0.0)\n"
    "        * gl_FrontMaterial.shininess * 0.01;\n"
    "    c += gl_FrontLightProduct[0].specular * s;\n"
    "  }\n"
    "  /* light 1: a spot with attenuation */\n"
    "  vec3 v1 = gl_LightSource[1].position.xyz - e.xyz;\n"
    "  float dist = length(v1);\n"
    "  vec3 l1 = v1 / dist;\n"
    "  float att = 1.0 / (gl_LightSource[1].constantAttenuation\n"
    "      + gl_LightSource[1].linearAttenuation * dist\n"
    "      + gl_LightSource[1].quadraticAttenuation * dist * dist);\n"
    "  float sd = dot(-l1, normalize(gl_LightSource[1].spotDirection));\n"
    "  float spot = sd < gl_LightSource[1].spotCosCutoff ? 0.0\n"
    "      : sd * gl_LightSource[1].spotExponent * 0.05;\n"
    "  c += att * spot * (gl_LightSource[1].diffuse * gl_FrontMaterial.diffuse\n"
    "      * max(dot(n, l1), 0.0) + gl_LightSource[1].ambient * gl_FrontMaterial.ambient);\n"
    "  c.a = gl_FrontMaterial.diffuse.a;\n"
    "  gl_FrontColor = clamp(c, 0.0, 1.0);\n"
    "  gl_Position = ftransform();\n"
    "}\n";

static const char *VS_MISC =
    "void main() {\n"
    "  vec4 e = gl_ModelViewMatrix * gl_Vertex;\n"
    "  float f = clamp((gl_Fog.end + e.z) * gl_Fog.scale, 0.0, 1.0);\n"
    "  vec4 back = gl_BackMaterial.diffuse * gl_LightModel.ambient\n"
    "      + gl_BackLightModelProduct.sceneColor + gl_BackLightProduct[2].diffuse;\n"
    "  float k = dot(gl_ClipPlane[3], e) * 0.2 + gl_DepthRange.diff * 0.3 + gl_DepthRange.near;\n"
    "  vec4 t = gl_TextureEnvColor[1] * 0.3 + vec4(dot(gl_EyePlaneS[0], e),\n"
    "      dot(gl_ObjectPlaneT[2], gl_Vertex), gl_Point.size * 0.1,\n"
    "      gl_Point.sizeMax * 0.001 + gl_Point.distanceLinearAttenuation) * 0.2;\n"
    "  gl_FrontColor = mix(gl_Fog.color, gl_Color * back + vec4(fract(k)) + t, f);\n"
    "  gl_Position = ftransform();\n"
    "}\n";

/* A fragment shader reading state uniforms that fit its 64 uniform words. */
static const char *FS_STATE =
    "void main() {\n"
    "  float f = clamp((gl_Fog.end - gl_FragCoord.z * 4.0) * gl_Fog.scale, 0.0, 1.0);\n"
    "  vec4 m = gl_FrontMaterial.diffuse * gl_Color + gl_FrontMaterial.emission\n"
    "      + gl_LightModel.ambient * gl_FrontMaterial.ambient;\n"
    "  gl_FragColor = vec4(mix(gl_Fog.color.rgb, m.rgb, f), m.a + gl_DepthRange.far * 0.1);\n"
    "}\n";

/* Per-pixel lighting: the fragment shader reads light 0 and its products. */
static const char *VS_PIXEL =
    "varying vec3 n;\n"
    "void main() {\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  gl_Position = ftransform();\n"
    "}\n";

static const char *FS_PIXEL =
    "varying vec3 n;\n"
    "void main() {\n"
    "  vec3 nn = normalize(n);\n"
    "  float d = max(dot(nn, normalize(gl_LightSource[0].position.xyz)), 0.0);\n"
    "  float s = max(dot(nn, gl_LightSource[0].halfVector.xyz), 0.0);\n"
    "  vec4 c = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].ambient\n"
    "      + gl_FrontLightProduct[0].diffuse * d\n"
    "      + gl_FrontLightProduct[0].specular * s * gl_FrontMaterial.shininess * 0.01;\n"
    "  gl_FragColor = vec4(c.rgb, gl_FrontMaterial.diffuse.a);\n"
    "}\n";

static void lights(int variant)
{
    static const GLfloat dir[4] = {0.3f, 0.8f, 1.0f, 0.0f};
    static const GLfloat pos[4] = {-0.5f, 0.4f, 1.5f, 1.0f};
    static const GLfloat spot[3] = {0.2f, -0.3f, -1.0f};
    GLfloat c[4] = {0.9f, 0.7f - 0.2f * (float)variant, 0.5f, 1.0f};
    GLfloat amb[4] = {0.15f, 0.1f, 0.2f * (float)variant, 1.0f};
    GLfloat mat[4] = {0.8f, 0.6f, 0.3f + 0.2f * (float)variant, 0.75f};
    GLfloat spec[4] = {0.7f, 0.7f, 0.9f, 1.0f};
    GLfloat em[4] = {0.05f, 0.0f, 0.1f, 1.0f};
    glPushMatrix();
    glLoadIdentity();
    glRotatef(20.0f + 15.0f * (float)variant, 0.0f, 1.0f, 0.3f);
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT1, GL_POSITION, pos);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot);
    glPopMatrix();
    glLightfv(GL_LIGHT0, GL_DIFFUSE, c);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, c);
    glLightfv(GL_LIGHT1, GL_AMBIENT, amb);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f + 20.0f * (float)variant);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0f + 10.0f * (float)variant);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.6f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.1f);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, mat);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT, GL_EMISSION, em);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.0f + 40.0f * (float)variant);
    glMaterialfv(GL_BACK, GL_DIFFUSE, c);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
}

static void sphere(float cx, float cy, float r)
{
    int i, j;
    for (i = 0; i < 8; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= 12; j++) {
            int k;
            for (k = 0; k < 2; k++) {
                float th = 3.14159265f * (float)(i + k) / 8.0f;
                float ph = 2.0f * 3.14159265f * (float)j / 12.0f;
                float x = sinf(th) * cosf(ph), y = cosf(th), z = sinf(th) * sinf(ph);
                glNormal3f(x, y, z);
                glVertex3f(cx + r * x, cy + r * y, r * z);
            }
        }
        glEnd();
    }
}

static void draw_all(const GLuint *progs, int n)
{
    static const GLdouble plane[4] = {0.5, -1.0, 0.2, 0.1};
    int v;
    (void)n;
    frag_begin_frame(GL_LESS);
    glClipPlane(GL_CLIP_PLANE3, plane);
    glDepthRange(0.1, 0.9);
    {
        static const GLfloat fog[4] = {0.6f, 0.5f, 0.4f, 1.0f};
        glFogfv(GL_FOG_COLOR, fog);
        glFogf(GL_FOG_START, 1.0f);
        glFogf(GL_FOG_END, 3.5f);
    }
    glUseProgram(progs[0]);
    for (v = 0; v < 2; v++) {
        lights(v);
        sphere(-0.45f + 0.9f * (float)v, 0.35f, 0.4f);
    }
    {
        static const GLfloat env[4] = {0.2f, 0.9f, 0.4f, 0.6f};
        static const GLfloat eye[4] = {0.3f, -0.5f, 0.8f, 0.2f};
        static const GLfloat obj[4] = {-0.6f, 0.4f, 0.1f, 0.5f};
        static const GLfloat att[3] = {1.0f, 0.25f, 0.0f};
        glPointSize(3.5f);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glActiveTexture(GL_TEXTURE1);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
        glActiveTexture(GL_TEXTURE2);
        glTexGenfv(GL_T, GL_OBJECT_PLANE, obj);
        glActiveTexture(GL_TEXTURE0);
        glPushMatrix();
        glRotatef(40.0f, 1.0f, 0.0f, 0.0f);
        glTexGenfv(GL_S, GL_EYE_PLANE, eye);
        glPopMatrix();
    }
    glUseProgram(progs[1]);
    sphere(0.0f, -0.45f, 0.4f);
    frag_random_tris(3);
    glUseProgram(progs[2]);
    frag_random_tris(3);
    glUseProgram(progs[3]);
    sphere(0.5f, -0.5f, 0.35f);
    glDepthRange(0.0, 1.0);
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    progs[0] = vert_program(VS_LIGHT, NULL, NULL);
    progs[1] = vert_program(VS_MISC, NULL, NULL);
    progs[2] = frag_program(FS_STATE);
    progs[3] = vert_program(VS_PIXEL, FS_PIXEL, NULL);
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 4, make, draw_all);
}
