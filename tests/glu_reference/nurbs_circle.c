/* Rational NURBS: a circle as a quadratic curve with nine homogeneous control points
 * (GL_MAP1_VERTEX_4), at default sampling and with GLU_DOMAIN_DISTANCE, and a quarter
 * cylinder as a rational surface (GL_MAP2_VERTEX_4), lit with GL_AUTO_NORMAL.
 * 200x200 frames, raw RGBA to argv[1]. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define S 200

int main(int argc, char **argv) {
  GLfloat w = 0.70710678f;
  GLfloat circ[9][4] = {{1, 0, 0, 1}, {w, w, 0, w}, {0, 1, 0, 1}, {-w, w, 0, w}, {-1, 0, 0, 1},
                        {-w, -w, 0, w}, {0, -1, 0, 1}, {w, -w, 0, w}, {1, 0, 0, 1}};
  GLfloat knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  /* Half cylinder: s around (three rational points per quarter), t along z. */
  GLfloat cyl[5][2][4];
  GLfloat sk[8] = {0, 0, 0, 1, 1, 2, 2, 2};
  GLfloat tk[4] = {0, 0, 1, 1};
  GLfloat ring[5][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1}};
  GLfloat light[4] = {1, 1, 2, 0};
  unsigned char *buf = malloc(S * S * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLUnurbs *nb;
  FILE *f;
  int i, j, frame;
  if (argc < 2 || !buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S, S)) return 2;
  f = fopen(argv[1], "wb");
  nb = gluNewNurbsRenderer();
  if (!f || !nb) return 2;
  for (i = 0; i < 5; i++)
    for (j = 0; j < 2; j++) {
      GLfloat ww = ring[i][2] ? 1.0f : w;
      cyl[i][j][0] = ring[i][0] * ww;
      cyl[i][j][1] = ring[i][1] * ww;
      cyl[i][j][2] = (j ? 1.5f : -1.5f) * ww;
      cyl[i][j][3] = ww;
    }
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-2, 2, -2, 2, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  for (frame = 0; frame < 4; frame++) {
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    if (frame < 2) {
      glDisable(GL_LIGHTING);
      glColor3f(1, 1, 0.5f);
      if (frame == 1) {
        gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
        gluNurbsProperty(nb, GLU_U_STEP, 5);
      }
      glScalef(1.7f, 1.3f, 1);
      gluBeginCurve(nb);
      gluNurbsCurve(nb, 12, knots, 4, &circ[0][0], 3, GL_MAP1_VERTEX_4);
      gluEndCurve(nb);
    } else {
      gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
      gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, frame == 2 ? 50.0f : 15.0f);
      glEnable(GL_LIGHTING);
      glEnable(GL_LIGHT0);
      glRotatef(30, 1, 0, 0);
      glRotatef(frame == 2 ? 20 : -40, 0, 1, 0);
      gluBeginSurface(nb);
      gluNurbsSurface(nb, 8, sk, 4, tk, 2 * 4, 4, &cyl[0][0][0], 3, 2, GL_MAP2_VERTEX_4);
      gluEndSurface(nb);
    }
    glFinish();
    fwrite(buf, 1, S * S * 4, f);
  }
  fclose(f);
  gluDeleteNurbsRenderer(nb);
  OSMesaDestroyContext(ctx);
  return 0;
}
