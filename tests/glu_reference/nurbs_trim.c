/* The Red Book's trim.c: a lit bicubic bumpy surface with an outer counterclockwise
 * piecewise-linear boundary and a clockwise hole made of a NURBS curve and a
 * polyline; then a second frame with a rational (GLU_MAP1_TRIM_3) circular hole and a
 * third drawn as GLU_OUTLINE_PATCH. 200x200 frames, raw RGBA to argv[1]. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define S 200

static GLfloat ctl[4][4][3];

int main(int argc, char **argv) {
  GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  GLfloat edge[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  GLfloat curve_pt[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.5f}};
  GLfloat curve_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  GLfloat pwl[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
  /* A circle of radius 0.2 about (0.5, 0.5), clockwise, as nine rational points. */
  GLfloat w = 0.70710678f;
  GLfloat circ[9][3] = {{0.7f, 0.5f, 1}, {0.7f * w, 0.3f * w, w}, {0.5f, 0.3f, 1},
                        {0.3f * w, 0.3f * w, w}, {0.3f, 0.5f, 1}, {0.3f * w, 0.7f * w, w},
                        {0.5f, 0.7f, 1}, {0.7f * w, 0.7f * w, w}, {0.7f, 0.5f, 1}};
  GLfloat circ_knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  GLfloat diffuse[4] = {0.7f, 0.7f, 0.7f, 1}, specular[4] = {1, 1, 1, 1};
  unsigned char *buf = malloc(S * S * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLUnurbs *nb;
  FILE *f;
  int u, v, frame;
  if (argc < 2 || !buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S, S)) return 2;
  f = fopen(argv[1], "wb");
  nb = gluNewNurbsRenderer();
  if (!f || !nb) return 2;
  for (u = 0; u < 4; u++)
    for (v = 0; v < 4; v++) {
      ctl[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
      ctl[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
      ctl[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
    }
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 100);
  glMatrixMode(GL_PROJECTION);
  gluPerspective(45.0, 1.0, 3.0, 8.0);
  glMatrixMode(GL_MODELVIEW);
  gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 25.0);
  for (frame = 0; frame < 3; frame++) {
    gluNurbsProperty(nb, GLU_DISPLAY_MODE, frame == 2 ? GLU_OUTLINE_PATCH : GLU_FILL);
    if (frame == 2) glDisable(GL_LIGHTING);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glRotatef(330, 1, 0, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    gluBeginSurface(nb);
    gluNurbsSurface(nb, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluBeginTrim(nb);
    gluPwlCurve(nb, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nb);
    gluBeginTrim(nb);
    if (frame == 1) {
      gluNurbsCurve(nb, 12, circ_knots, 3, &circ[0][0], 3, GLU_MAP1_TRIM_3);
    } else {
      gluNurbsCurve(nb, 8, curve_knots, 2, &curve_pt[0][0], 4, GLU_MAP1_TRIM_2);
      gluPwlCurve(nb, 3, &pwl[0][0], 2, GLU_MAP1_TRIM_2);
    }
    gluEndTrim(nb);
    gluEndSurface(nb);
    glFinish();
    fwrite(buf, 1, S * S * 4, f);
  }
  fclose(f);
  gluDeleteNurbsRenderer(nb);
  OSMesaDestroyContext(ctx);
  return 0;
}
