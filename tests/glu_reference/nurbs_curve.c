/* NURBS curves (Red Book style): a cubic Bezier, a uniform cubic B-spline and a
 * nonuniform quadratic with a double knot, each drawn under several sampling settings
 * (default path length, tolerance 10 and 3, domain distance with U_STEP 7 and 40,
 * parametric error) with a colour map on one of them. One 200x200 frame per setting,
 * written as raw RGBA to argv[1]. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define S 200

static GLfloat bez[4][3] = {{-4, -4, 0}, {-2, 4, 0}, {2, -4, 0}, {4, 4, 0}};
static GLfloat bez_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static GLfloat spl[7][3] = {{-4, 0, 0}, {-3, 3, 0}, {-1, -3, 1}, {0, 3, 0}, {1, -2, 0}, {3, 3, -1}, {4, -1, 0}};
static GLfloat spl_knots[11] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
static GLfloat quad[6][3] = {{-4, -3, 0}, {-2, 1, 0}, {0, -2, 0}, {1, 3, 0}, {3, 0, 0}, {4, 3, 0}};
static GLfloat quad_knots[9] = {0, 0, 0, 0.7f, 2, 2, 3.1f, 4, 4};
static GLfloat quad_knots_end[9] = {0, 0, 0, 0.7f, 2, 2, 3.1f, 4, 4};
static GLfloat colors[6][4] = {{1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 1, 1}, {0, 0, 1, 1}, {1, 0, 1, 1}};

int main(int argc, char **argv) {
  unsigned char *buf = malloc(S * S * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLUnurbs *nb;
  FILE *f;
  int setting;
  if (argc < 2 || !buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S, S)) return 2;
  f = fopen(argv[1], "wb");
  nb = gluNewNurbsRenderer();
  if (!f || !nb) return 2;
  (void)quad_knots_end;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(-5.0, 5.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  for (setting = 0; setting < 7; setting++) {
    switch (setting) {
    case 0: break;
    case 1: gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 10); break;
    case 2: gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 3); break;
    case 3: gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
            gluNurbsProperty(nb, GLU_U_STEP, 7); break;
    case 4: gluNurbsProperty(nb, GLU_U_STEP, 40); break;
    case 5: gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_PARAMETRIC_ERROR);
            gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 0.5f); break;
    case 6: gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
            gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 50); break;
    }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    if (setting == 6) {
      glTranslatef(0.3f, 0.2f, 0);
      glRotatef(25, 0, 0, 1);
      glScalef(0.6f, 0.6f, 1);
    }
    glColor3f(1, 1, 1);
    gluBeginCurve(nb);
    gluNurbsCurve(nb, 8, bez_knots, 3, &bez[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(nb);
    glColor3f(0.2f, 0.8f, 1);
    gluBeginCurve(nb);
    gluNurbsCurve(nb, 11, spl_knots, 3, &spl[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(nb);
    gluBeginCurve(nb);
    gluNurbsCurve(nb, 9, quad_knots, 4, &colors[0][0], 3, GL_MAP1_COLOR_4);
    gluNurbsCurve(nb, 9, quad_knots, 3, &quad[0][0], 3, GL_MAP1_VERTEX_3);
    gluEndCurve(nb);
    glFinish();
    fwrite(buf, 1, S * S * 4, f);
  }
  fclose(f);
  gluDeleteNurbsRenderer(nb);
  OSMesaDestroyContext(ctx);
  return 0;
}
