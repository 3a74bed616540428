/*
 * GLU's mipmap builders, gluUnProject4 and gluCheckExtension, printed: every level's
 * size and texels (as a checksum plus the first texel) after gluBuild*Mipmaps and
 * gluBuild*MipmapLevels with various levels, sizes (powers of two or not), formats
 * and types, the codes they return for bad arguments, gluUnProject4 results and
 * gluCheckExtension answers. tests/glut_tutorials.rs runs it linked with softglut's
 * GLU and with SGI's libGLU, both on Mesa's OSMesa, and compares the output.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

static void dump(GLenum target, const char *what, int r)
{
    int l;
    printf("%s -> %d\n", what, r);
    for (l = 0; l < 12; l++) {
        GLint w = 0, h = 0, d = 0;
        static unsigned char buf[64 * 64 * 4];
        unsigned sum = 0;
        int i;
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_DEPTH, &d);
        if (!w)
            continue;
        glGetTexImage(target, l, GL_RGBA, GL_UNSIGNED_BYTE, buf);
        for (i = 0; i < w * h * d * 4; i++)
            sum = sum * 31 + buf[i];
        printf("  level %d: %dx%dx%d sum %08x first %d %d %d %d\n", l, w, h, d, sum, buf[0],
               buf[1], buf[2], buf[3]);
    }
}

static GLuint tex[64];
static int k = 0;

#define T(target, call) \
    glBindTexture(target, tex[k++]); \
    dump(target, #call, call)

int main(void)
{
    unsigned char *img = malloc(64 * 64 * 4 * 4);
    float *fimg = malloc(16 * 8 * 4 * sizeof(float));
    unsigned char *fb = calloc(64 * 64, 4);
    const GLubyte *list = (const GLubyte *)"GL_a GL_bb GL_c";
    int i;
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);

    OSMesaMakeCurrent(c, fb, GL_UNSIGNED_BYTE, 64, 64);
    for (i = 0; i < 64 * 64 * 4 * 4; i++)
        img[i] = (unsigned char)((i * 7 + (i >> 5) * 13) ^ (i >> 9));
    for (i = 0; i < 16 * 8 * 4; i++)
        fimg[i] = (float)((i * 37) % 101) / 100.0f;
    glGenTextures(64, tex);

    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 4, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 1, 3, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 2, 2, 5, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 2, 3, 6, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 2, 3, 7, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 1, 0, 3, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 2, 1, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 12, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 3, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 12, 6, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGB, 5, 3, GL_RGB, GL_UNSIGNED_BYTE, 0, 0, 2, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_FLOAT, 0, 0, 4, fimg));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, 0x1234, 0, 0, 4, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 0, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 4, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, -1, 4, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_LUMINANCE_ALPHA, 16, 16, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 0, 0, 4, img));
    T(GL_TEXTURE_1D, gluBuild1DMipmapLevels(GL_TEXTURE_1D, GL_RGBA, 16, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 4, img));
    T(GL_TEXTURE_1D, gluBuild1DMipmapLevels(GL_TEXTURE_1D, GL_RGBA, 16, GL_RGBA, GL_UNSIGNED_BYTE, 1, 1, 3, img));
    T(GL_TEXTURE_1D, gluBuild1DMipmapLevels(GL_TEXTURE_1D, GL_RGBA, 10, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3, img));
    T(GL_TEXTURE_3D, gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, 8, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3, img));
    T(GL_TEXTURE_3D, gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, 8, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, 0, 1, 2, img));
    T(GL_TEXTURE_3D, gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 2, img));
    T(GL_TEXTURE_3D, gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, 8, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, img));
    /* Not here: 3D RGB images (SGI's GLU loses the end of the second level), sizes
     * that are not powers of two in gluBuild3DMipmaps or with a dimension of 1 (its
     * scaling differs there, and a 3x1x1 image comes out black). */
    T(GL_TEXTURE_2D, gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 6, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 7, 3, GL_RGB, GL_UNSIGNED_BYTE, img));
    T(GL_TEXTURE_2D, gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, img));
    T(GL_TEXTURE_1D, gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, 16, GL_RGBA, GL_UNSIGNED_BYTE, img));

    {
        GLdouble m[16] = { 1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1 };
        GLdouble p[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.2, -1, 0, 0, -2.2, 0 };
        GLint v[4] = { 0, 0, 64, 64 };
        GLdouble o[4];
        int r = gluUnProject4(10, 20, 0.3, 1.0, m, p, v, 0.1, 0.9, o, o + 1, o + 2, o + 3);
        printf("unproject4 %d %.10g %.10g %.10g %.10g\n", r, o[0], o[1], o[2], o[3]);
        r = gluUnProject4(10, 20, 0.3, 0.5, m, p, v, 0.0, 1.0, o, o + 1, o + 2, o + 3);
        printf("unproject4 %d %.10g %.10g %.10g %.10g\n", r, o[0], o[1], o[2], o[3]);
    }
    printf("check %d %d %d %d %d %d\n", gluCheckExtension((const GLubyte *)"GL_a", list),
           gluCheckExtension((const GLubyte *)"GL_bb", list),
           gluCheckExtension((const GLubyte *)"GL_b", list),
           gluCheckExtension((const GLubyte *)"GL_c", list),
           gluCheckExtension((const GLubyte *)"GL_a GL_bb", list),
           gluCheckExtension((const GLubyte *)"", list));
    printf("version %s\n", (const char *)gluGetString(GLU_VERSION));
    OSMesaDestroyContext(c);
    return 0;
}
