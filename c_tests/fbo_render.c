/* fbo_render: drawing into framebuffer objects (GL_ARB_framebuffer_object).
 * - Renderbuffers: RGBA8 colour with DEPTH24_STENCIL8, drawn with depth and stencil
 *   tests, read back as colour, depth (float and uint) and stencil.  The FBO is
 *   smaller than the window and not square, so a y flip would show.
 * - Render to texture: a 2D texture level 0, then glGenerateMipmap; a cube-map face;
 *   a 3D-texture layer; drawn into the window with the textures.
 * - A depth-only object with a DEPTH_COMPONENT24 texture (glDrawBuffer/glReadBuffer
 *   GL_NONE, colour mask off), used as a shadow map with GL_COMPARE_R_TO_TEXTURE.
 * - glDrawPixels, glBitmap, glCopyPixels and glCopyTexSubImage2D with an object
 *   bound, and culling with glFrontFace(GL_CW) (the object is drawn unflipped, as
 *   llvmpipe draws objects, so the winding must still pick the same faces).
 * The window image, the read-backs and glGet values are compared with llvmpipe. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "fbo_common.h"

#define W 96
#define H 80
#define FW 61
#define FH 43

static void tri_scene(float z0)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.93f, -0.87f, z0);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.81f, -0.71f, -0.5f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-0.33f, 0.89f, 0.1f);
    glColor4f(1.0f, 1.0f, 0.0f, 0.5f);
    glVertex3f(-0.71f, 0.73f, 0.2f);
    glVertex3f(0.91f, 0.23f, 0.2f);
    glVertex3f(0.13f, -0.97f, 0.2f);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    unsigned char px[FW * FH * 4], st[FW * FH];
    float dz[FW * FH];
    GLuint du[FW * FH];
    GLuint fb[4], rb[2], tex[4];
    GLint v[8];
    unsigned char bits[8] = {0x18, 0x3c, 0x7e, 0xff, 0xff, 0x7e, 0x3c, 0x18};
    unsigned char small[6 * 5 * 4];
    int i, face;

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* 1. renderbuffers */
    glGenFramebuffers(4, fb);
    glGenRenderbuffers(2, rb);
    sgl_fbo_rgba8_ds(fb[0], rb[0], rb[1], FW, FH);
    v[0] = (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glGetIntegerv(GL_DEPTH_BITS, &v[1]);
    glGetIntegerv(GL_STENCIL_BITS, &v[2]);
    glGetIntegerv(GL_ALPHA_BITS, &v[3]);
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v[4]);
    sgl_text(out, "rb_state", "%x %d %d %d %d", v[0], v[1], v[2], v[3], v[4] == (GLint)fb[0]);
    glViewport(0, 0, FW, FH);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 3, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
    glShadeModel(GL_SMOOTH);
    tri_scene(0.5f);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glBegin(GL_TRIANGLES); /* clockwise in GL: front, drawn */
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(0.2f, 0.9f, -0.9f);
    glVertex3f(0.9f, 0.9f, -0.9f);
    glVertex3f(0.2f, 0.3f, -0.9f);
    glColor3f(1.0f, 0.0f, 1.0f); /* counter-clockwise: back, culled */
    glVertex3f(-0.9f, -0.2f, -0.9f);
    glVertex3f(-0.2f, -0.2f, -0.9f);
    glVertex3f(-0.9f, 0.4f, -0.9f);
    glEnd();
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    /* pixel rectangles into the object */
    for (i = 0; i < 6 * 5 * 4; i++)
        small[i] = (unsigned char)(i * 37 + 11);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, FW, 0.0, FH, -1.0, 1.0);
    glRasterPos2i(3, 30);
    glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, small);
    glColor3f(0.0f, 1.0f, 1.0f);
    glRasterPos2i(50, 2);
    /* one byte per row: the default alignment of 4 would read 29 bytes of `bits` */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glRasterPos2i(40, 30);
    glCopyPixels(3, 30, 6, 5, GL_COLOR);
    glLoadIdentity();
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, "rb_color", FW, FH, 4, "RGBA", FW * 4, 1, px);
    glReadPixels(0, 0, FW, FH, GL_DEPTH_COMPONENT, GL_FLOAT, dz);
    sgl_data(out, "rb_depth_float", sizeof dz, dz);
    glReadPixels(0, 0, FW, FH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, du);
    sgl_data(out, "rb_depth_uint", sizeof du, du);
    /* FW bytes a row: the default pack alignment of 4 would pad rows past `st` */
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, FW, FH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    sgl_data(out, "rb_stencil", sizeof st, st);

    /* 2. render to a 2D texture, then mipmaps */
    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
    v[0] = (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glViewport(0, 0, 64, 32);
    glClearColor(0.0f, 0.0f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    tri_scene(0.0f);
    /* copy a piece of the object into the first texture's corner, from the object */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 50, 20, 2, 3, 10, 8);
    glGenerateMipmap(GL_TEXTURE_2D);
    sgl_text(out, "rtt_status", "%x", v[0]);

    /* cube face +Y and a 3D layer */
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    for (face = 0; face < 6; face++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGB, 16, 16, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, NULL);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_Y,
                           tex[1], 0);
    glViewport(0, 0, 16, 16);
    glClearColor(0.9f, 0.5f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    tri_scene(0.0f);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &v[0]);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, &v[1]);
    glBindTexture(GL_TEXTURE_3D, tex[2]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 16, 16, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, tex[2], 0, 2);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    tri_scene(0.0f);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &v[2]);
    sgl_text(out, "face_layer", "%x %d %d", v[0], v[1], v[2]);

    /* 3. a depth-only object as a shadow map */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 32, 32, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[3]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[3], 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    v[0] = (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glGetIntegerv(GL_DRAW_BUFFER, &v[1]);
    sgl_text(out, "shadow_status", "%x %x", v[0], v[1]);
    glViewport(0, 0, 32, 32);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 4.0f);
    tri_scene(-0.3f);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* back to the window: draw with everything */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetIntegerv(GL_DRAW_BUFFER, &v[0]);
    sgl_text(out, "window_draw_buffer", "%x", v[0]);
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glColor3f(1.0f, 1.0f, 1.0f);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glBegin(GL_QUADS); /* minified: uses the generated levels */
    glTexCoord2f(0, 0); glVertex2f(2, 2);
    glTexCoord2f(1, 0); glVertex2f(23, 2);
    glTexCoord2f(1, 1); glVertex2f(23, 13);
    glTexCoord2f(0, 1); glVertex2f(2, 13);
    glTexCoord2f(0, 0); glVertex2f(26, 2);
    glTexCoord2f(1, 0); glVertex2f(90, 2);
    glTexCoord2f(1, 1); glVertex2f(90, 34);
    glTexCoord2f(0, 1); glVertex2f(26, 34);
    glEnd();
    glBindTexture(GL_TEXTURE_2D, tex[3]); /* the shadow map, compared against r */
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0.45f); glVertex2f(2, 40);
    glTexCoord3f(1, 0, 0.45f); glVertex2f(34, 40);
    glTexCoord3f(1, 1, 0.75f); glVertex2f(34, 72);
    glTexCoord3f(0, 1, 0.75f); glVertex2f(2, 72);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBegin(GL_QUADS); /* the +Y face */
    glTexCoord3f(-1, 1, -1); glVertex2f(40, 40);
    glTexCoord3f(1, 1, -1); glVertex2f(60, 40);
    glTexCoord3f(1, 1, 1); glVertex2f(60, 60);
    glTexCoord3f(-1, 1, 1); glVertex2f(40, 60);
    glEnd();
    glDisable(GL_TEXTURE_CUBE_MAP);
    glEnable(GL_TEXTURE_3D);
    glBegin(GL_QUADS); /* layer 2 of 4: r = 2.5 / 4 */
    glTexCoord3f(0, 0, 0.625f); glVertex2f(64, 40);
    glTexCoord3f(1, 0, 0.625f); glVertex2f(94, 40);
    glTexCoord3f(1, 1, 0.625f); glVertex2f(94, 70);
    glTexCoord3f(0, 1, 0.625f); glVertex2f(64, 70);
    glEnd();
    glDisable(GL_TEXTURE_3D);
    /* the renderbuffer object's colour, blitted unscaled into the window */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, 30, 10, 60, 70, 90, 80, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glFinish();
    sgl_image(out, "window", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "%x", glGetError());
    glDeleteFramebuffers(4, fb);
    glDeleteRenderbuffers(2, rb);
    glDeleteTextures(4, tex);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
