/* NURBS errors and properties: misuse sequences and bad definitions, each followed by
 * the codes the GLU_NURBS_ERROR callback received; gluGetNurbsProperty after
 * gluNurbsProperty; and gluErrorString for every NURBS error. Text to argv[1]. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

static FILE *out;

static void GLAPIENTRY on_error(GLenum e) { fprintf(out, " %u", e); }

static GLfloat pts[8][4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1},
                            {4, 0, 0, 1}, {5, 1, 0, 1}, {6, 0, 0, 1}, {7, 1, 0, 1}};

static void curve(GLUnurbs *nb, GLint nk, GLfloat *k, GLint order) {
  gluBeginCurve(nb);
  gluNurbsCurve(nb, nk, k, 4, &pts[0][0], order, GL_MAP1_VERTEX_4);
  gluEndCurve(nb);
}

int main(int argc, char **argv) {
  static unsigned char buf[32 * 32 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  GLfloat good[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  GLfloat decreasing[8] = {0, 0, 0, 2, 1, 3, 3, 3};
  GLfloat empty[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  GLfloat multi[10] = {0, 1, 1, 1, 1, 2, 3, 4, 5, 6};
  GLfloat edge[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  GLfloat ctl[4][4][3] = {{{0}}};
  static const GLenum props[] = {GLU_SAMPLING_TOLERANCE, GLU_PARAMETRIC_TOLERANCE, GLU_U_STEP,
                                 GLU_V_STEP, GLU_SAMPLING_METHOD, GLU_DISPLAY_MODE, GLU_CULLING,
                                 GLU_AUTO_LOAD_MATRIX, GLU_NURBS_MODE};
  GLUnurbs *nb;
  GLenum e;
  unsigned i;
  GLfloat v;
  if (argc < 2 || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 32, 32)) return 2;
  out = fopen(argv[1], "w");
  nb = gluNewNurbsRenderer();
  if (!out || !nb) return 2;
  gluNurbsCallback(nb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
  for (i = 0; i < sizeof props / sizeof props[0]; i++) {
    v = -7;
    gluGetNurbsProperty(nb, props[i], &v);
    fprintf(out, "default %u = %g\n", props[i], v);
  }
#define CASE(name, body) do { fprintf(out, "%s:", name); body; fprintf(out, "\n"); } while (0)
  CASE("good", curve(nb, 8, good, 4));
  CASE("order 0", curve(nb, 8, good, 0));
  CASE("order 25", curve(nb, 8, good, 25));
  CASE("too few knots", curve(nb, 7, good, 4));
  CASE("empty range", curve(nb, 8, empty, 4));
  CASE("decreasing", curve(nb, 8, decreasing, 4));
  CASE("multiplicity", curve(nb, 10, multi, 4));
  CASE("end curve alone", gluEndCurve(nb));
  CASE("end surface alone", gluEndSurface(nb));
  CASE("trim outside surface", gluBeginTrim(nb));
  CASE("end trim alone", gluEndTrim(nb));
  CASE("bad property", gluNurbsProperty(nb, 12345, 1));
  CASE("bad method", gluNurbsProperty(nb, GLU_SAMPLING_METHOD, 12345));
  CASE("bad display", gluNurbsProperty(nb, GLU_DISPLAY_MODE, 12345));
  CASE("bad mode", gluNurbsProperty(nb, GLU_NURBS_MODE, 12345));
  CASE("bad get", gluGetNurbsProperty(nb, 12345, &v));
  CASE("bad callback", gluNurbsCallback(nb, 12345, NULL));
  CASE("trimmed ok", {
    gluBeginSurface(nb);
    gluNurbsSurface(nb, 8, good, 8, good, 12, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluBeginTrim(nb);
    gluPwlCurve(nb, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nb);
    gluEndSurface(nb);
  });
  CASE("surface bad order", {
    gluBeginSurface(nb);
    gluNurbsSurface(nb, 8, good, 8, good, 12, 3, &ctl[0][0][0], 0, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nb);
  });
  gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 12.5f);
  gluNurbsProperty(nb, GLU_PARAMETRIC_TOLERANCE, 0.25f);
  gluNurbsProperty(nb, GLU_U_STEP, 33);
  gluNurbsProperty(nb, GLU_V_STEP, 44);
  gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nb, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);
  gluNurbsProperty(nb, GLU_CULLING, GL_TRUE);
  gluNurbsProperty(nb, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
  gluNurbsProperty(nb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  for (i = 0; i < sizeof props / sizeof props[0]; i++) {
    v = -7;
    gluGetNurbsProperty(nb, props[i], &v);
    fprintf(out, "set %u = %g\n", props[i], v);
  }
  gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_OBJECT_PATH_LENGTH);
  gluGetNurbsProperty(nb, GLU_SAMPLING_METHOD, &v);
  fprintf(out, "object path length = %g\n", v);
  for (e = GLU_NURBS_ERROR1; e <= GLU_NURBS_ERROR37; e++)
    fprintf(out, "%u: %s\n", e, (const char *)gluErrorString(e));
  fclose(out);
  gluDeleteNurbsRenderer(nb);
  OSMesaDestroyContext(ctx);
  return 0;
}
