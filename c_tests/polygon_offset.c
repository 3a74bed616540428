/* polygon_offset: the classic hidden-line demo.  A depth-tested, lit, rotated
 * sphere-like mesh is filled with GL_POLYGON_OFFSET_FILL and its wireframe
 * (glPolygonMode GL_LINE) drawn on top; then the reverse (offset lines and
 * points pulled forward with OFFSET_LINE/OFFSET_POINT over an unoffset fill,
 * with back faces as points). */
#include "prims_common.h"

static void mesh(void)
{
    int i, j;
    for (i = 0; i < 8; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= 12; j++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float th = 3.14159265f * (float)(i + k) / 8.0f;
                float ph = 6.2831853f * (float)j / 12.0f;
                float x = sinf(th) * cosf(ph), y = cosf(th), z = sinf(th) * sinf(ph);
                glNormal3f(x, y, z);
                glVertex3f(x, y, z);
            }
        }
        glEnd();
    }
}

static void setup_view(void)
{
    GLfloat pos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 6.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.6f);
    glRotatef(23.0f, 1.0f, 0.3f, 0.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_DEPTH_TEST);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    prims_begin();
    setup_view();

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    mesh();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 1.0f, 0.2f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    mesh();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    prims_end(out, "hidden_line");

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(0.2f, 0.35f, 0.8f);
    mesh();
    glEnable(GL_POLYGON_OFFSET_LINE);
    glEnable(GL_POLYGON_OFFSET_POINT);
    glPolygonOffset(-1.5f, -4.0f);
    glColor3f(1.0f, 0.4f, 0.4f);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPointSize(2.0f);
    mesh();
    prims_end(out, "pulled_forward");
    prims_close(out);
    return 0;
}
