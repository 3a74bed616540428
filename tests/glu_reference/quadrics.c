/* Every GLU quadric (sphere, cylinder, cone, disk, partial disk, and a few edge shapes)
 * in every combination of normals, orientation, draw style and texture coordinates, lit
 * and textured, each drawn into a 128x128 frame; the frames are written one after another
 * as raw RGBA to argv[1]. Flat normals with GLU_POINT or GLU_SILHOUETTE are left out:
 * libGLU reads normal tables it never filled there. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define S 128

static void shape(GLUquadric *q, int k) {
  switch (k) {
  case 0: gluSphere(q, 1.2, 20, 16); break;
  case 1: gluSphere(q, 1.0, 7, 5); break;
  case 2: gluCylinder(q, 1.0, 0.4, 1.8, 18, 5); break;
  case 3: gluCylinder(q, 0.0, 0.9, 1.5, 12, 3); break;
  case 4: gluDisk(q, 0.3, 1.4, 20, 4); break;
  case 5: gluDisk(q, 0.0, 1.3, 16, 3); break;
  case 6: gluPartialDisk(q, 0.3, 1.4, 20, 4, 30, 200); break;
  case 7: gluPartialDisk(q, 0.0, 1.2, 9, 2, 45, -120); break;
  case 8: gluPartialDisk(q, 1.0, 1.0, 12, 2, 0, 360); break;
  }
}

int main(int argc, char **argv) {
  static const GLenum normals[3] = {GLU_SMOOTH, GLU_FLAT, GLU_NONE};
  static const GLenum styles[4] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
  static unsigned char tex[16 * 16 * 3];
  float light[4] = {2, 3, 4, 0}, spec[4] = {1, 1, 1, 1};
  unsigned char *buf = malloc(S * S * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLUquadric *q;
  FILE *f;
  int n, o, st, t, k, i;
  if (argc < 2 || !buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S, S)) return 2;
  f = fopen(argv[1], "wb");
  q = gluNewQuadric();
  if (!f || !q) return 2;
  for (i = 0; i < 16 * 16; i++) {
    tex[i * 3] = (unsigned char)(i * 7);
    tex[i * 3 + 1] = (unsigned char)((i % 16) * 16);
    tex[i * 3 + 2] = (unsigned char)((i / 16) * 16);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
  glPointSize(2);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.6, 0.6, -0.6, 0.6, 2, 20);
  glMatrixMode(GL_MODELVIEW);
  for (n = 0; n < 3; n++)
    for (o = 0; o < 2; o++)
      for (st = 0; st < 4; st++)
        for (t = 0; t < 2; t++)
          for (k = 0; k < 9; k++) {
            if (normals[n] == GLU_FLAT && (styles[st] == GLU_POINT || styles[st] == GLU_SILHOUETTE))
              continue;
            gluQuadricNormals(q, normals[n]);
            gluQuadricOrientation(q, o ? GLU_INSIDE : GLU_OUTSIDE);
            gluQuadricDrawStyle(q, styles[st]);
            gluQuadricTexture(q, (GLboolean)t);
            if (t) glEnable(GL_TEXTURE_2D); else glDisable(GL_TEXTURE_2D);
            glNormal3f(0.3f, 0.5f, 0.8f); /* what flat fans start from */
            glClearColor(0.1f, 0.1f, 0.1f, 1);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(0, 0, -5);
            glRotatef(20 + 40 * (k & 1), 1, 0, 0);
            glRotatef(30, 0, 1, 0);
            shape(q, k);
            glFinish();
            fwrite(buf, 1, S * S * 4, f);
          }
  gluDeleteQuadric(q);
  fclose(f);
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
