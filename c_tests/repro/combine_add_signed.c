/* combine_add_signed: GL_COMBINE_ALPHA = GL_ADD_SIGNED with
 * row 0: arg0 = PRIMARY alpha (SRC_ALPHA), arg1 = PRIMARY (ONE_MINUS_SRC_ALPHA)
 * row 1: the same operands swapped,
 * for primary alpha a = k/255 in column k (256x4 buffer, prints alphas != 128).
 * Real result is exactly 0.5 -> 127.5 -> 128 (round half even).
 * llvmpipe row 0: 127 for odd k in 65..127 (as if f32 a + ((1-a) - 0.5));
 * llvmpipe row 1: 128 everywhere.  softgl: 128 everywhere in both rows. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf = malloc(256 * 4 * 4), white[4*3] = {255,255,255,255,255,255,255,255,255,255,255,255};
    GLuint t; int k, row;
    OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 256, 4);
    glMatrixMode(GL_PROJECTION); glOrtho(0, 256, 0, 4, -1, 1); glMatrixMode(GL_MODELVIEW);
    glGenTextures(1, &t); glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, white);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD_SIGNED);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (row = 0; row < 2; row++) {
        if (row == 1) glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_SRC_ALPHA), glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glBegin(GL_QUADS);
        for (k = 0; k < 256; k++) {
            glColor4ub(200, 100, 50, (GLubyte)k);
            glTexCoord2f(0.5f, 0.5f);
            glVertex2f(k, row); glVertex2f(k + 1, row); glVertex2f(k + 1, row + 1); glVertex2f(k, row + 1);
        }
        glEnd();
    }
    glFinish();
    for (row = 0; row < 2; row++) {
        printf("row %d alphas != 128:", row);
        for (k = 0; k < 256; k++) if (buf[row * 1024 + 4 * k + 3] != 128) printf(" %d:%d", k, buf[row * 1024 + 4 * k + 3]);
        printf("\n");
    }
    return 0;
}
