/* frag_lod: texture lookups with a level-of-detail argument, texelFetch and
 * textureSize. texture2D and texture2DProj with a bias (a varying one and a
 * uniform one), textureLod, texture2DLod, textureProjLod, shadow2DLod and
 * textureCube/textureLod on a cube map without mipmaps (whose LOD argument
 * is ignored), a bias and a LOD on a mipmapped cube map (each pixel's rho
 * from its own direction) and a mipmapped 3D texture, on mipmapped textures whose minification and magnification
 * image filters match (llvmpipe's 8-bit path) or differ (its float path,
 * with a texture LOD bias and MIN/MAX_LOD clamps). texelFetch at texels and
 * levels inside and outside the texture (RGBA and LUMINANCE, whose missing
 * alpha reads 1), and textureSize of levels inside and beyond the mipmap
 * chain. Drawn into the window and into a framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#define FW 130
#define FH 97
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_BIAS =
    "uniform sampler2D a;\n"
    "uniform sampler2D c;\n"
    "uniform float ub;\n"
    "void main() {\n"
    "  vec2 st = gl_TexCoord[0].st * 3.0;\n"
    "  vec4 x = texture2D(a, st, gl_Color.r * 6.0 - 2.0);\n"
    "  vec4 y = texture2DProj(c, vec3(st, gl_TexCoord[0].q + 0.5), ub);\n"
    "  vec4 z = texture2D(a, gl_TexCoord[1].st, gl_Color.g * 3.0);\n"
    "  gl_FragColor = x * 0.4 + y * 0.3 + z * 0.3;\n"
    "}\n";

static const char *FS_LOD =
    "#version 130\n"
    "uniform sampler2D a;\n"
    "uniform sampler2D b;\n"
    "uniform sampler2D c;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  vec2 st = gl_TexCoord[0].st * 2.0;\n"
    "  vec4 x = textureLod(a, st, gl_Color.g * 8.0 - 1.5);\n"
    "  vec4 y = texture2DLod(b, st.ts, gl_Color.b * 7.0);\n"
    "  vec4 z = textureProjLod(c, vec3(st, 1.5), 2.5 - gl_Color.r * 3.0);\n"
    "  vec4 w = textureLod(b, gl_TexCoord[1].st, 1.0);\n"
    "  o = x * 0.3 + y * 0.3 + z * 0.2 + w * 0.2;\n"
    "}\n";

static const char *FS_OTHER =
    "#version 130\n"
    "uniform samplerCube q;\n"
    "uniform sampler2DShadow d;\n"
    "uniform sampler2D c;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  vec3 n = gl_TexCoord[0].xyz * 2.0 - 1.0;\n"
    "  vec4 x = textureLod(q, n, gl_Color.r * 4.0);\n"
    "  float s = textureLod(d, vec3(gl_TexCoord[0].st, gl_Color.g), 3.0);\n"
    "  vec4 z = texture(c, gl_TexCoord[0].st * 4.0, gl_Color.b * 4.0 - 2.0);\n"
    "  o = vec4(x.rgb * 0.4 + z.rgb * 0.4 + s * 0.2, 1.0);\n"
    "}\n";

static const char *FS_FETCH =
    "#version 130\n"
    "uniform sampler2D a;\n"
    "uniform sampler2D l;\n"
    "uniform int ul;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_TexCoord[0].st * 90.0) - 10;\n"
    "  int lv = int(gl_Color.r * 9.0) - 1;\n"
    "  vec4 x = texelFetch(a, p, lv);\n"
    "  vec4 y = texelFetch(l, ivec2(gl_TexCoord[0].ts * 22.0) - 3, int(gl_Color.g * 2.0));\n"
    "  ivec2 s0 = textureSize(a, 0);\n"
    "  ivec2 s1 = textureSize(a, ul) + textureSize(a, ul + 6) + textureSize(a, -1);\n"
    "  ivec2 s2 = textureSize(l, 1) + textureSize(l, 2);\n"
    "  vec4 z = vec4(vec2(s0 + s1) / 128.0, vec2(s2) / 8.0);\n"
    "  o = x * 0.4 + y * 0.3 + z * 0.3;\n"
    "}\n";

static const char *FS_BIAS3 =
    "uniform samplerCube m;\n"
    "uniform sampler3D v;\n"
    "void main() {\n"
    "  vec3 n = gl_TexCoord[0].xyz * 2.0 - 1.0;\n"
    "  vec4 x = textureCube(m, n, gl_Color.r * 5.0 - 1.0);\n"
    "  vec4 y = texture3D(v, gl_TexCoord[0].xyz * 3.0, gl_Color.g * 4.0 - 1.5);\n"
    "  gl_FragColor = x * 0.5 + y * 0.5;\n"
    "}\n";

static const char *FS_LOD3 =
    "#version 130\n"
    "uniform samplerCube m;\n"
    "uniform sampler3D v;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  vec4 x = textureLod(m, gl_TexCoord[0].zyx - 0.5, gl_Color.b * 5.0);\n"
    "  vec4 y = textureLod(v, gl_TexCoord[0].yxz * 2.0, gl_Color.r * 4.0 - 0.5);\n"
    "  o = x * 0.5 + y * 0.5;\n"
    "}\n";

#define NPROG 6

static void draw_all(const GLuint *progs, int n)
{
    frag_each_program(progs, n, 6);
    glUseProgram(0);
    frag_random_tris(3);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4], rb[FW * FH * 4];
    static unsigned char vol[8 * 8 * 8 * 4];
    GLuint tex[8], progs[NPROG];
    int face;

    glGenTextures(8, tex);
    /* a: trilinear (the same image filter both ways: the 8-bit path) */
    glActiveTexture(GL_TEXTURE0);
    frag_mipmapped_texture(tex[0], img);
    /* b: NEAREST_MIPMAP_NEAREST and NEAREST (the filters match) */
    glActiveTexture(GL_TEXTURE1);
    frag_mipmapped_texture(tex[1], img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* c: LINEAR_MIPMAP_NEAREST and NEAREST (the filters differ: llvmpipe's
     * float path) with a LOD bias and MIN/MAX_LOD */
    glActiveTexture(GL_TEXTURE2);
    frag_mipmapped_texture(tex[2], img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.75f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.5f);
    glActiveTexture(GL_TEXTURE3);
    frag_cube_texture(tex[3], img);
    glActiveTexture(GL_TEXTURE4);
    frag_depth_texture(tex[4]);
    /* l: a 16x16 LUMINANCE texture with one more level */
    glActiveTexture(GL_TEXTURE5);
    glBindTexture(GL_TEXTURE_2D, tex[5]);
    frag_pattern(img, 16, 16, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    frag_pattern(img, 8, 8, 4);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    /* m: a mipmapped 16x16 cube map, trilinear */
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[6]);
    for (face = 0; face < 6; face++) {
        frag_pattern(img, 16, 16, face + 2);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 16, 16, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, img);
    }
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    /* v: a mipmapped 8x8x8 3D texture, NEAREST_MIPMAP_LINEAR and LINEAR */
    glActiveTexture(GL_TEXTURE7);
    glBindTexture(GL_TEXTURE_3D, tex[7]);
    frag_pattern(vol, 8, 64, 5);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glGenerateMipmap(GL_TEXTURE_3D);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
    glActiveTexture(GL_TEXTURE0);

    progs[0] = frag_program(FS_BIAS);
    frag_set_unit(progs[0], "a", 0);
    frag_set_unit(progs[0], "c", 2);
    glUniform1f(glGetUniformLocation(progs[0], "ub"), -1.25f);
    progs[1] = frag_program(FS_LOD);
    frag_set_unit(progs[1], "a", 0);
    frag_set_unit(progs[1], "b", 1);
    frag_set_unit(progs[1], "c", 2);
    progs[2] = frag_program(FS_OTHER);
    frag_set_unit(progs[2], "q", 3);
    frag_set_unit(progs[2], "d", 4);
    frag_set_unit(progs[2], "c", 2);
    progs[3] = frag_program(FS_FETCH);
    frag_set_unit(progs[3], "a", 0);
    frag_set_unit(progs[3], "l", 5);
    glUniform1i(glGetUniformLocation(progs[3], "ul"), 3);
    progs[4] = frag_program(FS_BIAS3);
    frag_set_unit(progs[4], "m", 6);
    frag_set_unit(progs[4], "v", 7);
    progs[5] = frag_program(FS_LOD3);
    frag_set_unit(progs[5], "m", 6);
    frag_set_unit(progs[5], "v", 7);

    frag_window_and_fbo(out, buf, rb, draw_all, progs, NPROG);
    return frag_end(out, "end", buf, ctx);
}
