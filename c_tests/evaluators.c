/* evaluators: Bezier curves (glMap1 + glEvalCoord1 / glEvalMesh1 / glEvalPoint1, colour
 * map) and Bezier patches (glMap2, glMapGrid2 + glEvalMesh2 GL_FILL with GL_AUTO_NORMAL
 * and lighting, a rational GL_MAP2_VERTEX_4 patch, a texture-coordinate map, GL_LINE and
 * GL_POINT meshes), glGetMap and the errors. The current attributes after evaluation
 * are not compared: Mesa's read back as colour (0,0,0,0) and unchanged normal and
 * texture coordinates (see the report of the osmesa15 work). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 128
#define H 96

static char log_buf[4096];
static size_t log_len;
#define LOG(...) (log_len += (size_t)snprintf(log_buf + log_len, sizeof log_buf - log_len, __VA_ARGS__))

int main(int argc, char **argv)
{
    static const GLfloat curve[4][3] = {
        {-0.9f, -0.8f, 0.0f}, {-0.5f, 0.9f, 0.0f}, {0.2f, -0.9f, 0.0f}, {0.9f, 0.7f, 0.0f}};
    static const GLfloat curve_col[3][4] = {
        {1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 1.0f}, {0.2f, 0.3f, 1.0f, 1.0f}};
    static const GLfloat lpos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    static const GLfloat diff[4] = {0.8f, 0.6f, 0.3f, 1.0f};
    static const GLfloat spec[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    GLfloat patch[4][4][3], rational[3][3][4], texmap[2][2][2] = {{{0, 0}, {0, 1}}, {{1, 0}, {1, 1}}};
    GLdouble dpatch[2][3][3];
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLfloat fv[64];
    GLint iv[64];
    GLdouble dv[8];
    int i, j;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            patch[i][j][0] = -0.9f + 0.6f * i;
            patch[i][j][1] = -0.9f + 0.6f * j;
            patch[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 0.9f : -0.3f + 0.1f * (i - j);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            float w = (i == 1 && j == 1) ? 2.0f : 1.0f;
            rational[i][j][0] = (-0.8f + 0.5f * i) * w;
            rational[i][j][1] = (-0.7f + 0.6f * j) * w;
            rational[i][j][2] = (i == 1 ? 0.5f : 0.0f) * w;
            rational[i][j][3] = w;
        }
    for (i = 0; i < 2; i++)
        for (j = 0; j < 3; j++) {
            dpatch[i][j][0] = 0.2 + 0.35 * i;
            dpatch[i][j][1] = -0.9 + 0.4 * j + 0.1 * i;
            dpatch[i][j][2] = 0.0;
        }

    /* 1: curves */
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 3, &curve_col[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i <= 30; i++)
        glEvalCoord1f((GLfloat)i / 30.0f);
    glEnd();
    glPushMatrix();
    glTranslatef(0.0f, 0.1f, 0.0f);
    glMapGrid1f(17, 0.1f, 0.95f);
    glEvalMesh1(GL_LINE, 0, 17);
    glTranslatef(0.0f, -0.2f, 0.0f);
    glEvalMesh1(GL_POINT, 2, 15);
    glBegin(GL_POINTS);
    for (i = 0; i < 17; i += 3)
        glEvalPoint1(i);
    glEnd();
    glPopMatrix();
    glDisable(GL_MAP1_COLOR_4);
    glDisable(GL_MAP1_VERTEX_3);
    glFinish();
    sgl_image(out, "curves", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 2: a lit bicubic patch with GL_AUTO_NORMAL */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.5, 0.5, -0.4, 0.4, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -2.6f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(12, 0.0f, 1.0f, 10, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 12, 0, 10);
    glFinish();
    sgl_image(out, "patch_autonormal", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 3: a rational patch (vertex 4) with auto normals, a textured-coordinate map
     * driving colour through GL_MAP2_COLOR_4 off, and a double-precision patch drawn
     * as lines and points without lighting */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_MAP2_VERTEX_3);
    glMap2f(GL_MAP2_VERTEX_4, -1.0f, 1.0f, 4, 3, 2.0f, 0.0f, 12, 3, &rational[0][0][0]);
    glEnable(GL_MAP2_VERTEX_4);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, -1.0f, 1.0f, 2, 2, 2.0f, 0.0f, 4, 2, &texmap[0][0][0]);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glMapGrid2d(9, -1.0, 1.0, 7, 2.0, 0.0);
    glEvalMesh2(GL_FILL, 1, 8, 0, 7);
    glDisable(GL_MAP2_VERTEX_4);
    glDisable(GL_LIGHTING);
    glDisable(GL_AUTO_NORMAL);
    glMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 9, 2, 0.0, 1.0, 3, 3, &dpatch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glColor3f(1.0f, 1.0f, 0.3f);
    glMapGrid2f(5, 0.0f, 1.0f, 6, 0.0f, 1.0f);
    glEvalMesh2(GL_LINE, 0, 5, 0, 6);
    glColor3f(0.2f, 1.0f, 1.0f);
    glTranslatef(-0.8f, 0.0f, 0.0f);
    glEvalMesh2(GL_POINT, 0, 5, 0, 6);
    glBegin(GL_TRIANGLES);
    glEvalPoint2(0, 0);
    glEvalPoint2(5, 0);
    glEvalPoint2(2, 6);
    glEvalCoord2f(0.9f, 0.1f);
    glEvalCoord2d(0.95, 0.9);
    glEvalCoord2f(0.6f, 0.5f);
    glEnd();
    glFinish();
    sgl_image(out, "rational_lines_points", W, H, 4, "RGBA", W * 4, 1, buf);

    /* glGetMap */
    glGetMapiv(GL_MAP2_VERTEX_4, GL_ORDER, iv);
    LOG("order %d %d\n", iv[0], iv[1]);
    glGetMapfv(GL_MAP2_VERTEX_4, GL_DOMAIN, fv);
    LOG("domain %g %g %g %g\n", fv[0], fv[1], fv[2], fv[3]);
    glGetMapdv(GL_MAP1_VERTEX_3, GL_COEFF, dv);
    LOG("coeff %g %g %g %g\n", dv[0], dv[1], dv[2], dv[3]);
    glGetMapiv(GL_MAP1_COLOR_4, GL_COEFF, iv);
    LOG("icoeff %d %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3], iv[4]);
    glGetMapfv(GL_MAP2_NORMAL, GL_COEFF, fv);
    glGetMapiv(GL_MAP1_TEXTURE_COORD_4, GL_ORDER, iv);
    LOG("default normal %g %g %g order %d\n", fv[0], fv[1], fv[2], iv[0]);
    LOG("err %x\n", glGetError());

    /* errors */
    glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 4, &curve[0][0]);
    LOG("u1==u2 %x\n", glGetError());
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 4, &curve[0][0]);
    LOG("stride %x\n", glGetError());
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 0, &curve[0][0]);
    LOG("order0 %x\n", glGetError());
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 31, &curve[0][0]);
    LOG("order31 %x\n", glGetError());
    glMap1f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    LOG("map1 with map2 target %x\n", glGetError());
    glMap1f(GL_TEXTURE_2D, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    LOG("bad target %x\n", glGetError());
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.5f, 0.5f, 12, 4, &patch[0][0][0]);
    LOG("v1==v2 %x\n", glGetError());
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 2, 4, &patch[0][0][0]);
    LOG("vstride %x\n", glGetError());
    glMapGrid1f(0, 0.0f, 1.0f);
    LOG("grid1 n0 %x\n", glGetError());
    glMapGrid2f(3, 0.0f, 1.0f, -1, 0.0f, 1.0f);
    LOG("grid2 n-1 %x\n", glGetError());
    glEvalMesh1(GL_FILL, 0, 3);
    LOG("mesh1 fill %x\n", glGetError());
    glEvalMesh2(GL_TRIANGLES, 0, 3, 0, 3);
    LOG("mesh2 bad %x\n", glGetError());
    glGetMapfv(GL_MAP1_VERTEX_3, GL_TEXTURE_2D, fv);
    LOG("getmap bad query %x\n", glGetError());
    glGetMapfv(GL_TEXTURE_2D, GL_ORDER, fv);
    LOG("getmap bad target %x\n", glGetError());
    glBegin(GL_POINTS);
    glMapGrid1f(3, 0.0f, 1.0f);
    glEnd();
    LOG("grid in begin %x\n", glGetError());
    glIsEnabled(GL_MAP2_VERTEX_3);
    LOG("enabled %d %d\n", glIsEnabled(GL_MAP2_VERTEX_3), glIsEnabled(GL_AUTO_NORMAL));

    sgl_text(out, "log", "%s", log_buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
