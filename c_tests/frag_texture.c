/* frag_texture: fragment shaders that sample textures at varyings: texture2D
 * on two units (a mipmapped LINEAR_MIPMAP_LINEAR REPEAT texture and a NEAREST
 * CLAMP_TO_EDGE one), texture2DProj with vec4 and vec3 coordinates,
 * textureCube, texture3D, texture1D, shadow2D on a depth texture with compare
 * mode, a sampler naming a unit with no complete texture (0,0,0,1), lookups
 * under a varying branch and in a user function, the 1.30 texture() and
 * textureProj(), a vertex shader's user varying as the coordinate, and the
 * sampler uniforms changed between draws; drawn in perspective (w and the
 * level of detail vary) with the depth test, mixed with fixed-function
 * texturing in the same frame (whose enables the shaders ignore). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS_TWO =
    "uniform sampler2D a;\n"
    "uniform sampler2D b;\n"
    "void main() {\n"
    "  vec4 x = texture2D(a, gl_TexCoord[0].st);\n"
    "  vec4 y = texture2D(b, gl_TexCoord[1].st);\n"
    "  gl_FragColor = x * 0.75 + y * gl_Color * 0.25;\n"
    "}\n";

static const char *FS_PROJ =
    "uniform sampler2D a;\n"
    "uniform sampler2D b;\n"
    "void main() {\n"
    "  vec4 x = texture2DProj(a, gl_TexCoord[0]);\n"
    "  vec4 y = texture2DProj(b, gl_TexCoord[1].xyw);\n"
    "  gl_FragColor = mix(x, y, gl_Color.r);\n"
    "}\n";

static const char *FS_CUBE3D =
    "uniform samplerCube c;\n"
    "uniform sampler3D v;\n"
    "uniform sampler1D o;\n"
    "void main() {\n"
    "  vec4 x = textureCube(c, gl_TexCoord[0].xyz);\n"
    "  vec4 y = texture3D(v, gl_TexCoord[1].stp);\n"
    "  vec4 z = texture1D(o, gl_TexCoord[1].t);\n"
    "  gl_FragColor = vec4(x.rg, y.b, 1.0) * 0.8 + z * 0.2;\n"
    "}\n";

static const char *FS_SHADOW =
    "uniform sampler2DShadow d;\n"
    "void main() {\n"
    "  vec4 s = shadow2D(d, gl_TexCoord[0].stp);\n"
    "  gl_FragColor = vec4(s.rgb * gl_Color.rgb, 1.0);\n"
    "}\n";

static const char *FS_BRANCH =
    "uniform sampler2D a;\n"
    "uniform sampler2D e;\n"
    "vec4 look(sampler2D s, vec2 p) { return texture2D(s, p); }\n"
    "void main() {\n"
    "  vec4 col;\n"
    "  if (gl_Color.r > 0.5)\n"
    "    col = texture2D(a, gl_TexCoord[1].ts);\n"
    "  else\n"
    "    col = look(e, gl_TexCoord[0].st) + vec4(0.2, 0.1, 0.0, 0.0);\n"
    "  gl_FragColor = col;\n"
    "}\n";

static const char *FS_130 =
    "#version 130\n"
    "uniform sampler2D a;\n"
    "uniform sampler2DShadow d;\n"
    "void main() {\n"
    "  float s = texture(d, gl_TexCoord[0].stp);\n"
    "  gl_FragColor = texture(a, gl_TexCoord[0].st) * 0.5\n"
    "               + textureProj(a, gl_TexCoord[1]) * 0.25 + vec4(s * 0.25);\n"
    "}\n";

static const char *VS_UV =
    "varying vec2 uv;\n"
    "varying vec3 dir;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  uv = gl_MultiTexCoord0.st * 1.5 + vec2(0.25, -0.5);\n"
    "  dir = vec3(gl_MultiTexCoord0.t, gl_MultiTexCoord1.s, 1.0 - gl_MultiTexCoord0.s);\n"
    "  gl_FrontColor = gl_Color;\n"
    "}\n";

static const char *FS_UV =
    "uniform sampler2D a;\n"
    "uniform samplerCube c;\n"
    "varying vec2 uv;\n"
    "varying vec3 dir;\n"
    "void main() {\n"
    "  gl_FragColor = texture2D(a, uv) * 0.5 + textureCube(c, dir) * 0.5;\n"
    "}\n";

/* A perspective quad over the view with texture coordinates (s, t) in
 * [0,1]^2, r rising from 0.2 to 0.8 across it (the shadow reference), q 1. */
static void quad(void)
{
    static const float v[4][2] = {{-1.1f, -1.1f}, {1.1f, -1.1f}, {1.1f, 1.1f}, {-1.1f, 1.1f}};
    int k;
    glBegin(GL_QUADS);
    for (k = 0; k < 4; k++) {
        float s = v[k][0] > 0 ? 1.0f : 0.0f, t = v[k][1] > 0 ? 1.0f : 0.0f;
        glColor4f(0.9f, 0.7f, 0.5f, 1.0f);
        glMultiTexCoord4f(GL_TEXTURE0, s, t, 0.2f + 0.6f * s, 1.0f);
        glMultiTexCoord4f(GL_TEXTURE1, t, s, 0.5f, 1.0f);
        glVertex3f(v[k][0], v[k][1], -0.6f * v[k][1]);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4], vol[8 * 8 * 8 * 4];
    GLuint tex[6];
    GLuint two, proj, cube3d, shadow, branch, p130, uvp;
    int i;

    glGenTextures(6, tex);
    /* unit 0: mipmapped 2D, trilinear, REPEAT */
    glActiveTexture(GL_TEXTURE0);
    frag_mipmapped_texture(tex[0], img);
    /* unit 1: 2D RGB, NEAREST, CLAMP_TO_EDGE; also a 1D texture */
    glActiveTexture(GL_TEXTURE1);
    frag_pattern_texture(tex[1], img, 16, 1, GL_RGB, GL_NEAREST, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_1D, tex[5]);
    frag_pattern(img, 32, 1, 0);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    /* unit 2: cube map, LINEAR */
    glActiveTexture(GL_TEXTURE2);
    frag_cube_texture(tex[2], img);
    /* unit 3: depth texture with compare mode */
    glActiveTexture(GL_TEXTURE3);
    frag_depth_texture(tex[3]);
    /* unit 4: 3D, LINEAR, REPEAT */
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_3D, tex[4]);
    for (i = 0; i < 8 * 8 * 8 * 4; i++)
        vol[i] = (unsigned char)(sgl_randf() * 255.0f);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    /* unit 5 has no texture: a sampler naming it reads (0,0,0,1) */
    glActiveTexture(GL_TEXTURE0);

    two = frag_program(FS_TWO);
    frag_set_unit(two, "a", 0);
    frag_set_unit(two, "b", 1);
    proj = frag_program(FS_PROJ);
    frag_set_unit(proj, "a", 0);
    frag_set_unit(proj, "b", 1);
    cube3d = frag_program(FS_CUBE3D);
    frag_set_unit(cube3d, "c", 2);
    frag_set_unit(cube3d, "v", 4);
    frag_set_unit(cube3d, "o", 1);
    shadow = frag_program(FS_SHADOW);
    frag_set_unit(shadow, "d", 3);
    branch = frag_program(FS_BRANCH);
    frag_set_unit(branch, "a", 0);
    frag_set_unit(branch, "e", 5);
    p130 = frag_program(FS_130);
    frag_set_unit(p130, "a", 0);
    frag_set_unit(p130, "d", 3);
    uvp = vert_program(VS_UV, FS_UV, NULL);
    frag_set_unit(uvp, "a", 0);
    frag_set_unit(uvp, "c", 2);

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    /* fixed-function texturing enabled on unit 0: the shaders ignore it */
    glEnable(GL_TEXTURE_2D);

    glUseProgram(two);
    frag_random_tris(10);
    glUseProgram(proj);
    frag_random_tris(10);
    glUseProgram(cube3d);
    frag_random_tris(10);
    glUseProgram(branch);
    frag_random_tris(10);
    glUseProgram(p130);
    frag_random_tris(8);
    glUseProgram(uvp);
    vert_random_tris(10);
    /* the samplers swapped between draws */
    frag_set_unit(two, "a", 1);
    frag_set_unit(two, "b", 0);
    frag_random_tris(6);
    glUseProgram(0);
    frag_random_tris(6);
    frag_output(out, "mixed", buf);

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(shadow);
    quad();
    glUseProgram(p130);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    quad();
    return frag_end(out, "shadow", buf, ctx);
}
