/* Hostile NURBS input: NaN and infinite control points and knots, bad knot vectors,
 * zero, negative and huge orders, negative and huge counts and strides, NULL arrays,
 * unknown map types, misnested begin/end calls, degenerate and self-crossing trim
 * loops, absurd sampling properties, and the tessellator callbacks on it all. The
 * program must finish (it prints how many errors it saw to argv[1]); run only with
 * softglut's GLU, since libGLU reads NULL arrays and huge counts as given. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned errors, vertices;
static void GLAPIENTRY on_error(GLenum e) { (void)e; errors++; }
static void GLAPIENTRY on_vertex(GLfloat *v) { (void)v; vertices++; }
static void GLAPIENTRY on_begin(GLenum m) { (void)m; }
static void GLAPIENTRY on_end(void) {}

int main(int argc, char **argv) {
  static unsigned char buf[64 * 64 * 4];
  static GLfloat pts[64][4], grid[8][8][4];
  static GLfloat knots[80], bad_knots[12] = {0, 1, 2, 3, 2, 1, 0, 5, 6, 7, 8, 9};
  GLfloat nanv = nanf(""), inf = INFINITY;
  GLfloat loop[5][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}, {0, 0}}; /* crosses itself */
  GLfloat dup[4][2] = {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};
  GLfloat nan_loop[4][2];
  static const GLfloat props[] = {0, -1, 1e30f, -1e30f, NAN, INFINITY, 100215, 100216, 100217, 100208, 100209};
  GLUnurbs *nb;
  FILE *f;
  int i, j, p, o, mode;
  if (argc < 2 || !OSMesaMakeCurrent(OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL), buf, GL_UNSIGNED_BYTE, 64, 64))
    return 2;
  for (i = 0; i < 80; i++) knots[i] = (GLfloat)(i / 4);
  for (i = 0; i < 64; i++) { pts[i][0] = (GLfloat)i; pts[i][1] = (GLfloat)(i % 3); pts[i][2] = 0; pts[i][3] = (GLfloat)(i % 2); }
  for (i = 0; i < 8; i++)
    for (j = 0; j < 8; j++) { grid[i][j][0] = (GLfloat)i; grid[i][j][1] = (GLfloat)j; grid[i][j][2] = (i + j) % 2 ? nanv : 0; grid[i][j][3] = (GLfloat)((i * j) % 3) - 1; }
  for (i = 0; i < 4; i++) { nan_loop[i][0] = nanv; nan_loop[i][1] = (GLfloat)i; }
  glMatrixMode(GL_PROJECTION);
  glOrtho(-10, 10, -10, 10, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  nb = gluNewNurbsRenderer();
  gluNurbsCallback(nb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
  gluNurbsCallback(nb, GLU_NURBS_BEGIN, (_GLUfuncptr)on_begin);
  gluNurbsCallback(nb, GLU_NURBS_VERTEX, (_GLUfuncptr)on_vertex);
  gluNurbsCallback(nb, GLU_NURBS_END, (_GLUfuncptr)on_end);
  /* NULL handles. */
  gluBeginCurve(NULL); gluEndCurve(NULL); gluBeginSurface(NULL); gluEndSurface(NULL);
  gluBeginTrim(NULL); gluEndTrim(NULL); gluNurbsProperty(NULL, GLU_U_STEP, 1);
  gluNurbsCurve(NULL, 8, knots, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
  gluDeleteNurbsRenderer(NULL);
  for (mode = 0; mode < 2; mode++) {
    gluNurbsProperty(nb, GLU_NURBS_MODE, mode ? GLU_NURBS_TESSELLATOR : GLU_NURBS_RENDERER);
    for (p = 0; p < (int)(sizeof props / sizeof props[0]); p++) {
      gluNurbsProperty(nb, GLU_SAMPLING_METHOD, props[p]);
      gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, props[p]);
      gluNurbsProperty(nb, GLU_PARAMETRIC_TOLERANCE, props[p]);
      gluNurbsProperty(nb, GLU_U_STEP, props[p]);
      gluNurbsProperty(nb, GLU_V_STEP, props[p]);
      gluNurbsProperty(nb, GLU_DISPLAY_MODE, props[p]);
      for (o = -2; o <= 30; o += 4) {
        /* Curves: orders from -2 to 30 over every knot vector. */
        gluBeginCurve(nb);
        gluNurbsCurve(nb, 64 + (o > 0 ? o : 0) > 80 ? 80 : 64 + (o > 0 ? o : 0), knots, 4, &pts[0][0], o, GL_MAP1_VERTEX_4);
        gluEndCurve(nb);
        gluBeginCurve(nb);
        gluNurbsCurve(nb, 12, bad_knots, 4, &pts[0][0], o, GL_MAP1_VERTEX_3);
        gluEndCurve(nb);
        gluBeginSurface(nb);
        gluNurbsSurface(nb, 12, knots, 12, knots, 8 * 4, 4, &grid[0][0][0], o, 4, GL_MAP2_VERTEX_4);
        gluEndSurface(nb);
      }
      /* NaN and infinite points and knots. */
      pts[3][1] = nanv; pts[5][0] = inf; knots[6] = nanv;
      gluBeginCurve(nb);
      gluNurbsCurve(nb, 12, knots, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluEndCurve(nb);
      knots[6] = 1;
      gluBeginCurve(nb);
      gluNurbsCurve(nb, 12, knots, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 12, knots, 4, &pts[0][0], 4, GL_MAP1_COLOR_4);
      gluEndCurve(nb);
      pts[3][1] = 0; pts[5][0] = 5;
      /* Negative and huge counts and strides, NULL arrays, unknown types. */
      gluBeginCurve(nb);
      gluNurbsCurve(nb, -5, knots, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 0x7fffffff, knots, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 8, knots, -4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 8, NULL, 4, &pts[0][0], 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 8, knots, 4, NULL, 4, GL_MAP1_VERTEX_4);
      gluNurbsCurve(nb, 8, knots, 4, &pts[0][0], 4, 0x1234);
      gluEndCurve(nb);
      gluBeginSurface(nb);
      gluNurbsSurface(nb, 0x7fffffff, knots, 8, knots, 4, 4, &grid[0][0][0], 4, 4, GL_MAP2_VERTEX_4);
      gluNurbsSurface(nb, 8, knots, -8, knots, 4, 4, &grid[0][0][0], 4, 4, GL_MAP2_VERTEX_4);
      gluNurbsSurface(nb, 8, knots, 8, knots, -4, 4, &grid[0][0][0], 4, 4, GL_MAP2_VERTEX_4);
      gluNurbsSurface(nb, 8, knots, 8, knots, 4, 4, NULL, 4, 4, GL_MAP2_VERTEX_4);
      gluNurbsSurface(nb, 8, knots, 8, knots, 4, 4, &grid[0][0][0], 4, 4, GL_MAP1_VERTEX_4);
      gluEndSurface(nb);
      /* Misnested calls and hostile trims. */
      gluEndTrim(nb); gluPwlCurve(nb, 5, &loop[0][0], 2, GLU_MAP1_TRIM_2);
      gluBeginTrim(nb); gluBeginTrim(nb); gluBeginCurve(nb); gluEndSurface(nb); gluEndCurve(nb);
      gluBeginSurface(nb);
      gluNurbsSurface(nb, 16, knots, 16, knots, 8 * 4, 4, &grid[0][0][0], 4, 4, GL_MAP2_VERTEX_4);
      gluBeginTrim(nb); gluPwlCurve(nb, 5, &loop[0][0], 2, GLU_MAP1_TRIM_2); gluEndTrim(nb);
      gluBeginTrim(nb); gluPwlCurve(nb, 4, &dup[0][0], 2, GLU_MAP1_TRIM_2); gluEndTrim(nb);
      gluBeginTrim(nb); gluPwlCurve(nb, 4, &nan_loop[0][0], 2, GLU_MAP1_TRIM_2); gluEndTrim(nb);
      gluBeginTrim(nb); gluPwlCurve(nb, 3, &pts[0][0], 4, GLU_MAP1_TRIM_3); gluEndTrim(nb);
      gluBeginTrim(nb); gluNurbsCurve(nb, 12, knots, 4, &pts[0][0], 4, GLU_MAP1_TRIM_3); gluEndTrim(nb);
      gluBeginTrim(nb); gluPwlCurve(nb, -3, &loop[0][0], 2, GLU_MAP1_TRIM_2);
      gluPwlCurve(nb, 3, &loop[0][0], -2, GLU_MAP1_TRIM_2); gluPwlCurve(nb, 3, NULL, 2, GLU_MAP1_TRIM_2);
      gluEndTrim(nb);
      gluBeginTrim(nb);
      gluEndSurface(nb);
    }
  }
  gluDeleteNurbsRenderer(nb);
  f = fopen(argv[1], "w");
  if (!f) return 2;
  fprintf(f, "%u errors, %u vertices\n", errors, vertices);
  fclose(f);
  return 0;
}
