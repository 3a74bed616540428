/* quad_diagonal: which diagonal splits a GL_QUADS quad (docs/llvmpipe-rules.md §5).
 * v0 and v2 are bright, v1 and v3 dark, so a v0-v2 split shows a bright
 * ridge and a v1-v3 split a dark valley.  Cells:
 *   0 smooth quad alone in its glBegin                (v0-v2)
 *   1 same, glBegin also holds an off-screen quad      (v1-v3)
 *   2 same, glBegin also holds a quad crossing an edge (v1-v3)
 *   3 flat shaded                                      (v1-v3)
 *   4 glDrawElements(GL_QUADS)                         (v1-v3)
 *   5 glDrawArrays(GL_QUADS)                           (v0-v2)
 *   6 two glBegin/glEnd pairs without a state change, the second off-screen:
 *     Mesa merges them into one draw, so the first is split v1-v3 too
 *   7 GL_QUAD_STRIP alone, and 8 GL_QUAD_STRIP with an off-screen part */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static const GLfloat qv[4][2] = {{3.3f, 5.1f}, {79.7f, 2.9f}, {71.1f, 80.3f}, {1.9f, 66.6f}};
static const GLfloat qc[4][3] = {{1.0f, 0.9f, 0.2f}, {0.0f, 0.1f, 0.4f},
                                 {0.9f, 1.0f, 0.8f}, {0.2f, 0.0f, 0.1f}};

static void quad_verts(float ox, float oy)
{
    int i;
    for (i = 0; i < 4; i++) {
        glColor3fv(qc[i]);
        glVertex2f(ox + qv[i][0], oy + qv[i][1]);
    }
}

static float cx(int cell) { return 0.37f + (cell % 3) * 85.0f; }
static float cy(int cell) { return 0.61f + (cell / 3) * 85.0f; }

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    GLfloat arr[4][5];
    static const GLubyte idx[4] = {0, 1, 2, 3};
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* Consecutive glBegin/glEnd pairs without a state change in between
     * are merged into one draw by Mesa, so each cell changes the matrix. */

    /* 0 */
    glPushMatrix();
    glTranslatef(cx(0), cy(0), 0.0f);
    glBegin(GL_QUADS);
    quad_verts(0.0f, 0.0f);
    glEnd();
    glPopMatrix();

    /* 1 */
    glPushMatrix();
    glTranslatef(cx(1), cy(1), 0.0f);
    glBegin(GL_QUADS);
    quad_verts(0.0f, 0.0f);
    quad_verts(-500.0f, -500.0f);
    glEnd();
    glPopMatrix();

    /* 2: the second quad crosses the right edge of the viewport */
    glPushMatrix();
    glTranslatef(cx(2), cy(2), 0.0f);
    glBegin(GL_QUADS);
    quad_verts(0.0f, 0.0f);
    quad_verts(30.3f, 60.7f);
    glEnd();
    glPopMatrix();

    /* 3 */
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    quad_verts(cx(3), cy(3));
    glEnd();
    glShadeModel(GL_SMOOTH);

    /* 4 and 5: vertex arrays */
    for (i = 0; i < 4; i++) {
        arr[i][0] = qc[i][0];
        arr[i][1] = qc[i][1];
        arr[i][2] = qc[i][2];
        arr[i][3] = qv[i][0];
        arr[i][4] = qv[i][1];
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(3, GL_FLOAT, sizeof arr[0], &arr[0][0]);
    glVertexPointer(2, GL_FLOAT, sizeof arr[0], &arr[0][3]);
    glPushMatrix();
    glTranslatef(cx(4), cy(4), 0.0f);
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, idx);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(cx(5), cy(5), 0.0f);
    glDrawArrays(GL_QUADS, 0, 4);
    glPopMatrix();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);

    /* 6: two begin/end pairs, no state change in between */
    glBegin(GL_QUADS);
    quad_verts(cx(6), cy(6));
    glEnd();
    glBegin(GL_QUADS);
    quad_verts(-300.0f, 100.0f);
    glEnd();

    /* 7 and 8: quad strips */
    glPushMatrix();
    glTranslatef(cx(7), cy(7), 0.0f);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 6; i++) {
        glColor3fv(qc[(i * 3) % 4]);
        glVertex2f(2.2f + (i / 2) * 37.7f + (i & 1) * 5.5f, (i & 1) ? 77.7f : 3.3f + i);
    }
    glEnd();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(cx(8), cy(8), 0.0f);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 6; i++) {
        glColor3fv(qc[(i * 3) % 4]);
        glVertex2f(2.2f + (i / 2) * 37.7f + (i & 1) * 5.5f, (i & 1) ? 77.7f : 3.3f + i);
    }
    glVertex2f(900.0f, 5.0f);
    glVertex2f(900.0f, 70.0f);
    glEnd();
    glPopMatrix();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
