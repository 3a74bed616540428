/* tex_multitexture: two texture units.  A brick-like base texture on unit 0
 * modulated by a luminance light map on unit 1 (a radial blob), each unit
 * with its own texture matrix (unit 0 scaled, unit 1 rotated and
 * translated).  Left half: immediate mode with glMultiTexCoord2f.  Right
 * half: vertex arrays with a texcoord array per unit selected through
 * glClientActiveTexture, drawn with glDrawArrays and glDrawElements, with
 * unit 1 in GL_ADD mode for the second mesh.  A perspective floor at the top
 * uses both units minified with mipmaps. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char base[32 * 32 * 4], light[16 * 16];
    GLuint tex[2];
    float verts[2 * 16], tc0[2 * 16], tc1[2 * 16], cols[4 * 16];
    float sverts[2 * 8], stc0[2 * 8], stc1[2 * 8], scols[4 * 8];
    GLushort idx[6 * 9];
    int i, j, x, y, n;

    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++) {
            int row = y / 8, mortar = (y % 8 == 0) || ((x + (row & 1) * 8) % 16 == 0);
            unsigned char *p = base + 4 * (y * 32 + x);
            p[0] = mortar ? 200 : (unsigned char)(150 + (x * 7 + y * 3) % 40);
            p[1] = mortar ? 195 : (unsigned char)(60 + (x * 3) % 25);
            p[2] = mortar ? 185 : (unsigned char)(40 + (y * 5) % 20);
            p[3] = 255;
        }
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            float dx = (x - 7.5f) / 7.5f, dy = (y - 7.5f) / 7.5f;
            float v = 1.0f - 0.8f * (dx * dx + dy * dy);
            light[y * 16 + x] = (unsigned char)(v < 0.1f ? 25 : v * 255.0f);
        }
    glGenTextures(2, tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    sgl_upload_mips(base, 32, 32);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE,
                 GL_UNSIGNED_BYTE, light);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    /* texture matrices, one per unit (GL_TEXTURE matrix mode follows the
     * active unit) */
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    glLoadIdentity();
    glScalef(2.3f, 1.7f, 1.0f);
    glActiveTexture(GL_TEXTURE1);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.0f);
    glRotatef(23.0f, 0.0f, 0.0f, 1.0f);
    glTranslatef(-0.53f, -0.47f, 0.0f);

    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* left: immediate mode */
    glBegin(GL_TRIANGLE_STRIP);
    glColor3f(1.0f, 0.93f, 0.87f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
    glVertex2f(3.3f, 5.7f);
    glColor3f(0.87f, 1.0f, 0.93f);
    glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
    glVertex2f(123.9f, 9.1f);
    glColor3f(0.93f, 0.87f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 1.0f);
    glVertex2f(7.1f, 121.3f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 1.0f);
    glVertex2f(125.7f, 118.9f);
    glEnd();

    /* right: a 4x4 vertex grid from arrays */
    n = 0;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++, n++) {
            verts[2 * n] = 131.3f + 40.1f * i + 3.1f * j;
            verts[2 * n + 1] = 3.7f + 39.3f * j - 2.3f * i;
            tc0[2 * n] = i / 3.0f;
            tc0[2 * n + 1] = j / 3.0f;
            tc1[2 * n] = 0.1f + 0.27f * i;
            tc1[2 * n + 1] = 0.05f + 0.3f * j;
            cols[4 * n] = 0.5f + 0.15f * i;
            cols[4 * n + 1] = 0.5f + 0.15f * j;
            cols[4 * n + 2] = 0.9f - 0.1f * i;
            cols[4 * n + 3] = 1.0f;
        }
    n = 0;
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            GLushort v = (GLushort)(j * 4 + i);
            idx[n++] = v;
            idx[n++] = (GLushort)(v + 1);
            idx[n++] = (GLushort)(v + 5);
            idx[n++] = v;
            idx[n++] = (GLushort)(v + 5);
            idx[n++] = (GLushort)(v + 4);
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, cols);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, tc0);
    glClientActiveTexture(GL_TEXTURE1);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, tc1);
    glDrawElements(GL_TRIANGLES, 54, GL_UNSIGNED_SHORT, idx);

    /* second mesh, shifted up, unit 1 adds the light instead */
    glActiveTexture(GL_TEXTURE1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(-3.1f, 123.3f, 0.0f);
    /* rows 0 and 1 reordered into strip order, then glDrawArrays */
    for (i = 0; i < 8; i++) {
        int k = (i & 1) ? 4 + i / 2 : i / 2;
        memcpy(sverts + 2 * i, verts + 2 * k, 2 * sizeof(float));
        memcpy(stc0 + 2 * i, tc0 + 2 * k, 2 * sizeof(float));
        memcpy(stc1 + 2 * i, tc1 + 2 * k, 2 * sizeof(float));
        memcpy(scols + 4 * i, cols + 4 * k, 4 * sizeof(float));
    }
    glVertexPointer(2, GL_FLOAT, 0, sverts);
    glColorPointer(4, GL_FLOAT, 0, scols);
    glTexCoordPointer(2, GL_FLOAT, 0, stc1); /* client active unit is 1 */
    glClientActiveTexture(GL_TEXTURE0);
    glTexCoordPointer(2, GL_FLOAT, 0, stc0);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 8);
    glClientActiveTexture(GL_TEXTURE1);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

    /* top left: a perspective floor, both units minified */
    glViewport(0, 128, 128, 128);
    glEnable(GL_DEPTH_TEST);
    sgl_ground_view(1.0);
    glActiveTexture(GL_TEXTURE0);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, -20.1f, 0.3f);
    glMultiTexCoord2f(GL_TEXTURE1, -2.1f, 0.1f);
    glVertex3f(-40.3f, 0.0f, 1.1f);
    glMultiTexCoord2f(GL_TEXTURE0, 20.3f, 0.3f);
    glMultiTexCoord2f(GL_TEXTURE1, 3.1f, 0.1f);
    glVertex3f(40.7f, 0.0f, 1.1f);
    glMultiTexCoord2f(GL_TEXTURE0, 20.3f, 60.7f);
    glMultiTexCoord2f(GL_TEXTURE1, 3.1f, 7.3f);
    glVertex3f(40.7f, 0.0f, -120.9f);
    glMultiTexCoord2f(GL_TEXTURE0, -20.1f, 60.7f);
    glMultiTexCoord2f(GL_TEXTURE1, -2.1f, 7.3f);
    glVertex3f(-40.3f, 0.0f, -120.9f);
    glEnd();

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
