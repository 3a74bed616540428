/* A robot arm built on the matrix stack (boxes as QUADS, TRIANGLES and POLYGONs, a
 * QUAD_STRIP cylinder) over a mipmapped, lit, textured floor, seen through gluPerspective
 * and gluLookAt. Written as raw RGBA bytes to argv[1]. Built against softgl with
 * softglut's GLU, and against Mesa with the system libGLU, the images must be identical:
 * a camera matrix one bit off moves scattered floor pixels by one step. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 640
#define H 480

static const float normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
static const int faces[6][4] = {{1, 2, 6, 5}, {0, 4, 7, 3}, {2, 3, 7, 6},
                                {0, 1, 5, 4}, {4, 5, 6, 7}, {0, 3, 2, 1}};

/* A box of half-extents (sx, sy, sz): mode 0 QUADS, 1 TRIANGLES, 2 one POLYGON a face. */
static void box(float sx, float sy, float sz, int mode) {
  float v[8][3];
  int i, k;
  for (i = 0; i < 8; i++) {
    v[i][0] = (i == 1 || i == 2 || i == 5 || i == 6) ? sx : -sx;
    v[i][1] = (i == 2 || i == 3 || i == 6 || i == 7) ? sy : -sy;
    v[i][2] = i >= 4 ? sz : -sz;
  }
  for (i = 0; i < 6; i++) {
    const int *f = faces[i];
    if (mode == 1) {
      glBegin(GL_TRIANGLES);
      glNormal3fv(normals[i]);
      glVertex3fv(v[f[0]]); glVertex3fv(v[f[1]]); glVertex3fv(v[f[2]]);
      glVertex3fv(v[f[0]]); glVertex3fv(v[f[2]]); glVertex3fv(v[f[3]]);
      glEnd();
    } else {
      glBegin(mode == 0 ? GL_QUADS : GL_POLYGON);
      glNormal3fv(normals[i]);
      for (k = 0; k < 4; k++) glVertex3fv(v[f[k]]);
      glEnd();
    }
  }
}

static void cylinder(float r, float h, int segments) {
  int i;
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= segments; i++) {
    float a = 6.2831853f * i / segments;
    glNormal3f(cosf(a), sinf(a), 0);
    glVertex3f(r * cosf(a), r * sinf(a), 0);
    glVertex3f(r * cosf(a), r * sinf(a), h);
  }
  glEnd();
}

int main(int argc, char **argv) {
  static unsigned char tex[64 * 64 * 4];
  float light[4] = {2, 5, 3, 1}, white[4] = {1, 1, 1, 1};
  float red[4] = {0.8f, 0.2f, 0.2f, 1}, green[4] = {0.2f, 0.7f, 0.3f, 1};
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  unsigned char *buf = malloc(W * H * 4);
  GLuint t;
  FILE *f;
  int x, y, i, j;
  if (argc < 2 || !ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H))
    return 2;
  for (y = 0; y < 64; y++)
    for (x = 0; x < 64; x++) {
      int c = ((x / 8) ^ (y / 8)) & 1;
      unsigned char *p = tex + (y * 64 + x) * 4;
      p[0] = c ? 220 : 60; p[1] = c ? 200 : 90; p[2] = c ? 180 : 120; p[3] = 255;
    }
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);

  glClearColor(0.1f, 0.1f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)W / H, 1.5, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(3.7, 3.1, 4.9, 0.0, 0.8, 0.0, 0.0, 1.0, 0.0);

  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  glNormal3f(0, 1, 0);
  for (i = -4; i < 4; i++)
    for (j = -4; j < 4; j++) {
      glTexCoord2f(i * 0.5f, j * 0.5f); glVertex3f(i, 0, j);
      glTexCoord2f(i * 0.5f, (j + 1) * 0.5f); glVertex3f(i, 0, j + 1);
      glTexCoord2f((i + 1) * 0.5f, (j + 1) * 0.5f); glVertex3f(i + 1, 0, j + 1);
      glTexCoord2f((i + 1) * 0.5f, j * 0.5f); glVertex3f(i + 1, 0, j);
    }
  glEnd();
  glDisable(GL_TEXTURE_2D);

  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  glPushMatrix();
  glTranslatef(0, 0.5f, 0);
  box(0.6f, 0.5f, 0.6f, 0);
  glTranslatef(0, 0.5f, 0);
  glRotatef(-90, 1, 0, 0);
  glRotatef(35, 0, 1, 0);
  cylinder(0.2f, 1.5f, 24);
  glTranslatef(0, 0, 1.5f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green);
  glRotatef(60, 0, 1, 0);
  glPushMatrix();
  glTranslatef(0, 0, 0.6f);
  box(0.15f, 0.15f, 0.6f, 1);
  glPopMatrix();
  glTranslatef(0, 0, 1.2f);
  box(0.25f, 0.1f, 0.1f, 2);
  glPopMatrix();
  glFinish();

  f = fopen(argv[1], "wb");
  if (!f) return 2;
  fwrite(buf, 1, W * H * 4, f);
  fclose(f);
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
