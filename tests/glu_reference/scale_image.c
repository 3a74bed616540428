/* gluScaleImage between every pair of the seven basic types (RGB, random data, floats
 * partly outside [0, 1]) for shrinking, enlarging, exact halving, identity and mixed
 * sizes; each result is written as raw bytes after its return code. Built against
 * softglut's GLU and against the system libGLU over Mesa, the outputs must be identical. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
  static const GLenum types[7] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                  GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
  static const int size[7] = {1, 1, 2, 2, 4, 4, 4};
  static const int dims[5][4] = {{13, 7, 29, 15}, {40, 40, 20, 20}, {33, 17, 8, 5},
                                 {5, 9, 5, 9}, {64, 1, 17, 3}};
  static unsigned char buf[16 * 16 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  unsigned seed = 7;
  FILE *f;
  int d, ti, to, i;
  if (argc < 2 || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16)) return 2;
  f = fopen(argv[1], "wb");
  if (!f) return 2;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (d = 0; d < 5; d++)
    for (ti = 0; ti < 7; ti++)
      for (to = 0; to < 7; to++) {
        int wi = dims[d][0], hi = dims[d][1], wo = dims[d][2], ho = dims[d][3];
        unsigned char *in = malloc((size_t)wi * hi * 3 * 4);
        unsigned char *out = calloc((size_t)wo * ho * 3 * 4, 1);
        int r;
        if (!in || !out) return 2;
        for (i = 0; i < wi * hi * 3 * size[ti]; i++) {
          seed = seed * 1103515245u + 12345u;
          in[i] = (unsigned char)(seed >> 16);
        }
        if (types[ti] == GL_FLOAT)
          for (i = 0; i < wi * hi * 3; i++) {
            seed = seed * 1103515245u + 12345u;
            ((float *)in)[i] = ((seed >> 8) & 0xffff) / 65535.0f * 1.2f - 0.1f;
          }
        r = gluScaleImage(GL_RGB, wi, hi, types[ti], in, wo, ho, types[to], out);
        fwrite(&r, sizeof r, 1, f);
        fwrite(out, 1, (size_t)wo * ho * 3 * size[to], f);
        free(in);
        free(out);
      }
  fclose(f);
  OSMesaDestroyContext(ctx);
  return 0;
}
