/* pbo: pixel buffer objects (GL 2.1, ARB_pixel_buffer_object) against Mesa's.
 * Unpacking from GL_PIXEL_UNPACK_BUFFER at offsets: glTexImage2D with row length and
 * skips, glTexSubImage2D, glDrawPixels (8- and 16-bit), glBitmap, glPolygonStipple,
 * glCompressedTexImage2D, and a display list compiled while the buffer is bound (the
 * list keeps the bytes of compile time). Packing into GL_PIXEL_PACK_BUFFER: glReadPixels
 * (colour with row length, depth as float), glGetTexImage, glGetPolygonStipple,
 * glGetCompressedTexImage, then the whole buffer read back through glMapBuffer. The
 * GL_INVALID_OPERATION cases: a range past the end, an offset not a multiple of the
 * type's size, a mapped buffer, an empty buffer. The bindings through glGetIntegerv,
 * glPushClientAttrib/glPopClientAttrib and glDeleteBuffers, and the extension string. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "errcheck.h"

#define W 64
#define H 64
#define SRC 4096
#define PACK 8192

#define OFS(n) ((void *)(size_t)(n))

static void bindings(const char *label)
{
    GLint pack = -1, unpack = -1;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack);
    sgl_text(out, "bind", "%s pack %d unpack %d err 0x%04x\n", label, pack, unpack,
             glGetError());
}

static void quad(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(x0, y0);
    glTexCoord2f(1, 0);
    glVertex2f(x1, y0);
    glTexCoord2f(1, 1);
    glVertex2f(x1, y1);
    glTexCoord2f(0, 1);
    glVertex2f(x0, y1);
    glEnd();
}

int main(int argc, char **argv)
{
    static unsigned char src[SRC], fill[PACK], dxt1[32];
    GLuint pbo[4], tex[2], list;
    unsigned char *buf;
    const unsigned char *mapped;
    const char *ext;
    OSMesaContext ctx;
    int i;

    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < SRC; i++)
        src[i] = (unsigned char)(i * 37 + 11 + (i >> 7));
    memset(fill, 0xCD, sizeof fill);
    for (i = 0; i < 32; i++)
        dxt1[i] = (unsigned char)(i * 53 + 7);

    ext = (const char *)glGetString(GL_EXTENSIONS);
    sgl_text(out, "ext", "ARB_pixel_buffer_object %d EXT_pixel_buffer_object %d\n",
             strstr(ext, "GL_ARB_pixel_buffer_object") != NULL,
             strstr(ext, "GL_EXT_pixel_buffer_object") != NULL);

    glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glGenBuffers(4, pbo);
    glGenTextures(2, tex);
    bindings("initial");

    /* a texture unpacked from the buffer at offset 64, rows of 20 pixels, skips 2 and 1 */
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[0]));
    E(glBufferData(GL_PIXEL_UNPACK_BUFFER, SRC, src, GL_STATIC_DRAW));
    bindings("unpack bound");
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFS(64)));
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    E(glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 8, GL_RGB, GL_UNSIGNED_BYTE, OFS(1000)));
    /* past the end, and a 16-bit image at an odd offset: nothing changes */
    E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, OFS(3500)));
    E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_SHORT, OFS(1)));
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad(-1.0f, -1.0f, -0.1f, -0.1f);
    glDisable(GL_TEXTURE_2D);

    /* glDrawPixels from the buffer */
    glRasterPos2f(0.05f, -0.95f);
    E(glDrawPixels(12, 10, GL_RGB, GL_UNSIGNED_BYTE, OFS(300)));
    glRasterPos2f(0.5f, -0.95f);
    E(glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_SHORT, OFS(3)));
    E(glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_SHORT, OFS(4)));
    E(glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));
    glRasterPos2f(0.7f, -0.95f);
    E(glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, OFS(SRC - 255)));
    E(glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, OFS(SRC - 256)));

    /* glBitmap and glPolygonStipple from the buffer */
    glColor3f(1.0f, 1.0f, 0.0f);
    glRasterPos2f(0.05f, -0.5f);
    E(glBitmap(16, 16, 0.0f, 0.0f, 0.0f, 0.0f, (const GLubyte *)OFS(512)));
    E(glBitmap(16, 16, 0.0f, 0.0f, 0.0f, 0.0f, (const GLubyte *)OFS(SRC - 16)));
    E(glPolygonStipple((const GLubyte *)OFS(1024)));
    E(glPolygonStipple((const GLubyte *)OFS(SRC - 100)));
    glEnable(GL_POLYGON_STIPPLE);
    glColor3f(0.3f, 0.9f, 0.6f);
    quad(-1.0f, 0.1f, -0.1f, 1.0f);
    glDisable(GL_POLYGON_STIPPLE);

    /* a mapped buffer cannot be read */
    mapped = glMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_READ_ONLY);
    sgl_text(out, "map", "unpack mapped %d err 0x%04x\n", mapped != NULL, glGetError());
    E(glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));
    E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));
    E(glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, (const GLubyte *)OFS(0)));
    E(glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER));

    /* an empty buffer */
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[1]));
    E(glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));

    /* a list compiled with the buffer bound keeps the bytes of compile time */
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[0]));
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glRasterPos2f(-0.95f, 0.85f);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, OFS(128));
    glEndList();
    sgl_text(out, "list", "compiled err 0x%04x\n", glGetError());
    E(glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 0, 1024, fill));
    glCallList(list);

    /* a compressed texture from the buffer */
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[2]));
    E(glBufferData(GL_PIXEL_UNPACK_BUFFER, 64, NULL, GL_STATIC_DRAW));
    E(glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 16, 32, dxt1));
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    E(glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32,
                             OFS(40)));
    E(glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32,
                             OFS(16)));
    glEnable(GL_TEXTURE_2D);
    quad(0.1f, 0.1f, 1.0f, 1.0f);
    glDisable(GL_TEXTURE_2D);
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0));
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* packing into a buffer */
    E(glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo[3]));
    E(glBufferData(GL_PIXEL_PACK_BUFFER, PACK, fill, GL_STREAM_READ));
    bindings("pack bound");
    glPixelStorei(GL_PACK_ROW_LENGTH, 40);
    E(glReadPixels(3, 5, 30, 20, GL_RGBA, GL_UNSIGNED_BYTE, OFS(32)));
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    E(glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));
    E(glReadPixels(0, 0, 4, 4, GL_RGBA, GL_FLOAT, OFS(2)));
    E(glReadPixels(60, 60, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT, OFS(4096)));
    E(glReadPixels(62, 62, 4, 4, GL_RGB, GL_UNSIGNED_BYTE, OFS(4200)));
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFS(5000)));
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFS(PACK - 1000)));
    E(glGetPolygonStipple((GLubyte *)OFS(7000)));
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    E(glGetCompressedTexImage(GL_TEXTURE_2D, 0, OFS(7200)));
    E(glGetCompressedTexImage(GL_TEXTURE_2D, 0, OFS(PACK - 8)));
    mapped = glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY);
    sgl_text(out, "map", "pack mapped %d err 0x%04x\n", mapped != NULL, glGetError());
    E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0)));
    if (mapped)
        sgl_data(out, "packed", PACK, mapped);
    E(glUnmapBuffer(GL_PIXEL_PACK_BUFFER));

    /* the bindings are pixel-store client state; deleting a buffer unbinds it */
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[0]));
    bindings("both bound");
    E(glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT));
    E(glBindBuffer(GL_PIXEL_PACK_BUFFER, 0));
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo[2]));
    bindings("changed");
    E(glPopClientAttrib());
    bindings("popped");
    E(glDeleteBuffers(1, &pbo[3]));
    bindings("pack deleted");
    E(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0));
    return sgl_end_scene(ctx, buf);
}
