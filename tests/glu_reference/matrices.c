/* GLU's matrix helpers on random input: the matrices gluLookAt, gluPerspective,
 * gluOrtho2D and gluPickMatrix leave on the stack, and gluProject's window coordinates,
 * written as raw bytes. Built once against softglut's GLU and once against the system
 * libGLU, both over Mesa's OSMesa, the two outputs must be identical. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned seed = 12345;
static double rnd(void) {
  seed = seed * 1103515245u + 12345u;
  return (double)((seed >> 8) & 0xffff) / 65536.0;
}

static void dump(FILE *f, GLenum which) {
  float m[16];
  glGetFloatv(which, m);
  fwrite(m, sizeof m[0], 16, f);
}

int main(int argc, char **argv) {
  static unsigned char buf[16 * 16 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  FILE *f;
  int t;
  if (argc < 2 || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16)) return 2;
  f = fopen(argv[1], "wb");
  if (!f) return 2;
  for (t = 0; t < 500; t++) {
    GLint vp[4];
    double mv[16], pj[16], x, y, z;
    int i, ok;
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef((float)(rnd() * 360.0), 0.3f, 1.0f, 0.2f);
    gluLookAt(rnd() * 20 - 10, rnd() * 10, rnd() * 20 - 10, rnd() - 0.5, rnd(), rnd() - 0.5,
              rnd() - 0.5, 1.0, rnd() - 0.5);
    dump(f, GL_MODELVIEW_MATRIX);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(10 + rnd() * 150, 0.25 + rnd() * 2, 0.05 + rnd(), 2 + rnd() * 500);
    dump(f, GL_PROJECTION_MATRIX);
    glLoadIdentity();
    gluOrtho2D(-rnd() * 100, rnd() * 100, -rnd() * 50, rnd() * 50);
    dump(f, GL_PROJECTION_MATRIX);
    vp[0] = (int)(rnd() * 20);
    vp[1] = (int)(rnd() * 20);
    vp[2] = 100 + (int)(rnd() * 500);
    vp[3] = 100 + (int)(rnd() * 400);
    glLoadIdentity();
    gluPickMatrix(rnd() * 600, rnd() * 500, 1 + rnd() * 10, 1 + rnd() * 10, vp);
    dump(f, GL_PROJECTION_MATRIX);
    for (i = 0; i < 16; i++) {
      mv[i] = rnd() * 2 - 1;
      pj[i] = rnd() * 2 - 1;
    }
    ok = gluProject(rnd(), rnd(), rnd(), mv, pj, vp, &x, &y, &z);
    fwrite(&ok, sizeof ok, 1, f);
    fwrite(&x, sizeof x, 1, f);
    fwrite(&y, sizeof y, 1, f);
    fwrite(&z, sizeof z, 1, f);
  }
  fclose(f);
  OSMesaDestroyContext(ctx);
  return 0;
}
