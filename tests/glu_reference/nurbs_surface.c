/* The Red Book's surface.c: a bicubic 4x4 bumpy surface over two patches in each
 * direction (uniform interior knot), lit with GL_AUTO_NORMAL, drawn filled and as
 * GLU_OUTLINE_POLYGON, with default and tighter sampling, at two angles; plus a
 * texture-coordinate and a colour map given as extra gluNurbsSurface calls; then
 * filled and outlined under GLU_DOMAIN_DISTANCE (U_STEP 20, V_STEP 13), then with a
 * GL_MAP2_NORMAL map instead of GL_AUTO_NORMAL, then unlit with colour and texture maps.
 * 200x200 frames, raw RGBA to argv[1]. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define S 200

static GLfloat ctl[5][5][3];
static GLfloat tex[2][2][2] = {{{0, 0}, {0, 1}}, {{1, 0}, {1, 1}}};
static GLfloat col[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 1}}};
static GLfloat nrm[2][2][3] = {{{-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}}, {{0.5f, -0.5f, 1}, {0.5f, 0.5f, 1}}};

int main(int argc, char **argv) {
  GLfloat knots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
  GLfloat lin[4] = {0, 0, 1, 1};
  GLfloat diffuse[4] = {0.7f, 0.7f, 0.7f, 1}, specular[4] = {1, 1, 1, 1};
  GLfloat light[4] = {1, 2, 3, 0};
  static unsigned char img[8 * 8 * 3];
  unsigned char *buf = malloc(S * S * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLUnurbs *nb;
  FILE *f;
  int u, v, frame, i;
  if (argc < 2 || !buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S, S)) return 2;
  f = fopen(argv[1], "wb");
  nb = gluNewNurbsRenderer();
  if (!f || !nb) return 2;
  for (u = 0; u < 5; u++)
    for (v = 0; v < 5; v++) {
      ctl[u][v][0] = 2.0f * ((GLfloat)u - 2.0f);
      ctl[u][v][1] = 2.0f * ((GLfloat)v - 2.0f);
      ctl[u][v][2] = ((u == 1 || u == 3) && (v == 1 || v == 3)) ? 3.0f : -1.0f;
      if (u == 2 && v == 2) ctl[u][v][2] = -3.0f;
    }
  for (i = 0; i < 64; i++) {
    img[i * 3] = (unsigned char)(((i & 1) ^ ((i >> 3) & 1)) * 255);
    img[i * 3 + 1] = (unsigned char)(i * 4);
    img[i * 3 + 2] = 128;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMatrixMode(GL_PROJECTION);
  gluPerspective(45.0, 1.0, 3.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  for (frame = 0; frame < 12; frame++) {
    int outline = frame & 1, tight = (frame >> 1) & 1, extra = (frame >> 2) & 1;
    if (frame == 8) {
      gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
      gluNurbsProperty(nb, GLU_U_STEP, 20);
      gluNurbsProperty(nb, GLU_V_STEP, 13);
    }
    gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, tight ? 10.0f : 25.0f);
    gluNurbsProperty(nb, GLU_DISPLAY_MODE, outline ? GLU_OUTLINE_POLYGON : GLU_FILL);
    if (outline) { glDisable(GL_LIGHTING); glColor3f(1, 1, 1); }
    else { glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); }
    if (extra && !outline) glEnable(GL_TEXTURE_2D); else glDisable(GL_TEXTURE_2D);
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -15);
    glRotatef(tight ? 300 : 330, 1, 0, 0);
    glRotatef(extra ? 20 : 0, 0, 0, 1);
    gluBeginSurface(nb);
    gluNurbsSurface(nb, 9, knots, 9, knots, 5 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    if (extra) {
      gluNurbsSurface(nb, 4, lin, 4, lin, 2 * 2, 2, &tex[0][0][0], 2, 2, GL_MAP2_TEXTURE_COORD_2);
      if (outline) gluNurbsSurface(nb, 4, lin, 4, lin, 2 * 4, 4, &col[0][0][0], 2, 2, GL_MAP2_COLOR_4);
    }
    if (frame == 10) {
      gluNurbsSurface(nb, 4, lin, 4, lin, 2 * 3, 3, &nrm[0][0][0], 2, 2, GL_MAP2_NORMAL);
      glDisable(GL_AUTO_NORMAL);
    }
    if (frame == 11) {
      glDisable(GL_LIGHTING);
      glEnable(GL_TEXTURE_2D);
      gluNurbsSurface(nb, 4, lin, 4, lin, 2 * 2, 2, &tex[0][0][0], 2, 2, GL_MAP2_TEXTURE_COORD_2);
      gluNurbsSurface(nb, 4, lin, 4, lin, 2 * 4, 4, &col[0][0][0], 2, 2, GL_MAP2_COLOR_4);
    }
    gluEndSurface(nb);
    glEnable(GL_AUTO_NORMAL);
    glFinish();
    fwrite(buf, 1, S * S * 4, f);
  }
  fclose(f);
  gluDeleteNurbsRenderer(nb);
  OSMesaDestroyContext(ctx);
  return 0;
}
