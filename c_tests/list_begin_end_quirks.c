/* Display-list corners of the glBegin/glEnd rule that piglit's gl-1.0-beginend-coverage
 * checks, as Mesa 22.3 behaves:
 * - a glDrawArrays inside the list's own glBegin under GL_COMPILE_AND_EXECUTE raises
 *   GL_INVALID_OPERATION (seen by glEnd) and draws nothing; compiled under GL_COMPILE it is
 *   skipped, with the error, when the list runs;
 * - glEndList inside the list's own glBegin ends the list, with GL_INVALID_OPERATION
 *   under GL_COMPILE_AND_EXECUTE;
 * - glTexParameterf/i compiled into a list are stored as glTexParameterfv with
 *   (param, 0, 0, 0), so GL_TEXTURE_BORDER_COLOR is accepted there (and refused outside). */
#include <GL/gl.h>
#include <GL/osmesa.h>

#include "common.h"

int main(int argc, char **argv) {
  static unsigned char buf[16 * 16 * 4];
  static const float v[6] = {0, 0, 0.5f, 0.5f, 0.2f, 0.2f};
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  FILE *f = sgl_open(argc, argv);
  GLuint l;
  GLint n;
  float b[4];
  SGL_CHECK(ctx && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16));
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);

  l = glGenLists(1);
  glNewList(l, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, 3);
  glEnd();
  sgl_text(f, "ce_draw_end", "0x%x\n", glGetError());
  glEndList();
  sgl_text(f, "ce_draw_endlist", "0x%x\n", glGetError());
  glCallList(l);
  sgl_text(f, "ce_draw_call", "0x%x\n", glGetError());

  l = glGenLists(1);
  glNewList(l, GL_COMPILE);
  glBegin(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, 3);
  glEnd();
  glEndList();
  sgl_text(f, "c_draw_compile", "0x%x\n", glGetError());
  glCallList(l);
  sgl_text(f, "c_draw_call", "0x%x\n", glGetError());

  l = glGenLists(1);
  glNewList(l, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_POINTS);
  glEndList();
  glEnd();
  sgl_text(f, "ce_endlist_end", "0x%x\n", glGetError());
  glGetIntegerv(GL_LIST_INDEX, &n);
  sgl_text(f, "ce_endlist_index", "%d\n", n);
  glEndList();
  sgl_text(f, "ce_endlist_again", "0x%x\n", glGetError());

  l = glGenLists(1);
  glNewList(l, GL_COMPILE);
  glBegin(GL_POINTS);
  glEndList();
  glEnd();
  sgl_text(f, "c_endlist_end", "0x%x\n", glGetError());
  glGetIntegerv(GL_LIST_INDEX, &n);
  sgl_text(f, "c_endlist_index", "%d\n", n);

  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  sgl_text(f, "border_outside", "0x%x\n", glGetError());
  l = glGenLists(1);
  glNewList(l, GL_COMPILE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.75f);
  glEndList();
  sgl_text(f, "border_compile", "0x%x\n", glGetError());
  glCallList(l);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b);
  sgl_text(f, "border_call", "0x%x %g %g %g %g\n", glGetError(), b[0], b[1], b[2], b[3]);
  l = glGenLists(1);
  glNewList(l, GL_COMPILE_AND_EXECUTE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, 0x1234);
  glEndList();
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b);
  sgl_text(f, "border_ce", "0x%x %g %g %g %g\n", glGetError(), b[0], b[1], b[2], b[3]);
  sgl_close(f);
  OSMesaDestroyContext(ctx);
  return 0;
}
