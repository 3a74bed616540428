/* attrib_stack: glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
 * Each row changes state after a push, draws, pops and draws again, so the picture shows
 * which state each group restored: enable bits, colour buffer (blend, colour mask), depth,
 * lighting, fog, texture binding and environment, viewport/scissor, current colour,
 * polygon (cull face), transform (matrix mode), and pushes compiled into a display list.
 * Text blocks: stack depths, overflow/underflow errors, glGet values after pops, and the
 * client stack (pixel store, vertex arrays). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static char text[8192];
static int len;

static void put(const char *what, double v)
{
    len += snprintf(text + len, sizeof text - len, "%s %g\n", what, v);
}

static GLint geti(GLenum e)
{
    GLint v = -1;
    glGetIntegerv(e, &v);
    return v;
}

static void tri(float x, float y, float z)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.1f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(x, y, z);
    glColor3f(0.1f, 1.0f, 0.3f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(x + 30.0f, y + 2.0f, z);
    glColor3f(0.2f, 0.3f, 1.0f);
    glTexCoord2f(0.5f, 1.0f);
    glVertex3f(x + 12.0f, y + 28.0f, z);
    glEnd();
}

/* a triangle in the current colour, in the other winding */
static void plain_cw(float x, float y)
{
    glBegin(GL_TRIANGLES);
    glVertex2f(x, y);
    glVertex2f(x + 12.0f, y + 28.0f);
    glVertex2f(x + 30.0f, y + 2.0f);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    GLuint tex[2], list;
    GLubyte texels[2][4 * 4 * 4];
    int i, k;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.25f, 0.25f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -100.0, 100.0);
    glMatrixMode(GL_MODELVIEW);

    for (k = 0; k < 2; k++)
        for (i = 0; i < 16; i++) {
            texels[k][4 * i + 0] = (GLubyte)(k ? 255 - i * 16 : i * 16);
            texels[k][4 * i + 1] = (GLubyte)((i % 4) * 80);
            texels[k][4 * i + 2] = (GLubyte)(k ? 200 : 40);
            texels[k][4 * i + 3] = 255;
        }
    glGenTextures(2, tex);
    for (k = 0; k < 2; k++) {
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[k]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, tex[0]);

    /* row 0: enable bits */
    glEnable(GL_DEPTH_TEST);
    glPushAttrib(GL_ENABLE_BIT);
    put("depth_after_push", geti(GL_ATTRIB_STACK_DEPTH));
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_CULL_FACE);
    glEnable(GL_TEXTURE_2D);
    tri(2.0f, 2.0f, 0.0f);
    glPopAttrib();
    put("depth_after_pop", geti(GL_ATTRIB_STACK_DEPTH));
    put("blend_enabled", glIsEnabled(GL_BLEND));
    put("depth_enabled", glIsEnabled(GL_DEPTH_TEST));
    put("texture2d_enabled", glIsEnabled(GL_TEXTURE_2D));
    put("blend_src_kept", geti(GL_BLEND_SRC));
    tri(40.0f, 2.0f, 0.0f);
    glDisable(GL_DEPTH_TEST);

    /* row 0 right: colour buffer group */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.9f);
    tri(80.0f, 2.0f, 0.0f);
    glPopAttrib();
    put("blend_func_dst", geti(GL_BLEND_DST));
    put("alpha_test", glIsEnabled(GL_ALPHA_TEST));
    tri(120.0f, 2.0f, 0.0f);
    glDisable(GL_BLEND);

    /* row 1: depth buffer group */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    tri(2.0f, 40.0f, 10.0f);
    glPushAttrib(GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_FALSE);
    glClearDepth(0.25);
    tri(10.0f, 44.0f, -20.0f);
    glPopAttrib();
    put("depth_func", geti(GL_DEPTH_FUNC));
    put("depth_writemask", geti(GL_DEPTH_WRITEMASK));
    tri(20.0f, 48.0f, -30.0f);
    glDisable(GL_DEPTH_TEST);

    /* row 1 right: lighting and fog */
    {
        static const GLfloat pos[4] = {0.2f, 0.4f, 1.0f, 0.0f};
        static const GLfloat red[4] = {1.0f, 0.2f, 0.2f, 1.0f};
        static const GLfloat blue[4] = {0.2f, 0.2f, 1.0f, 1.0f};
        static const GLfloat fogc[4] = {0.8f, 0.8f, 0.1f, 1.0f};
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
        glPushAttrib(GL_LIGHTING_BIT | GL_FOG_BIT);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
        glShadeModel(GL_FLAT);
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, -50.0f);
        glFogf(GL_FOG_END, 50.0f);
        glFogfv(GL_FOG_COLOR, fogc);
        tri(80.0f, 40.0f, 10.0f);
        glPopAttrib();
        put("fog_enabled", glIsEnabled(GL_FOG));
        put("shade_model", geti(GL_SHADE_MODEL));
        tri(120.0f, 40.0f, 10.0f);
        glDisable(GL_LIGHTING);
    }

    /* row 2: texture group */
    glEnable(GL_TEXTURE_2D);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    tri(2.0f, 80.0f, 0.0f);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPopAttrib();
    put("texture_binding", geti(GL_TEXTURE_BINDING_2D) == (GLint)tex[0]);
    {
        GLint f = -1;
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &f);
        put("tex0_mag_filter", f);
        glBindTexture(GL_TEXTURE_2D, tex[1]);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &f);
        put("tex1_mag_filter", f);
        glBindTexture(GL_TEXTURE_2D, tex[0]);
    }
    {
        GLint m = -1;
        glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &m);
        put("env_mode", m);
    }
    tri(40.0f, 80.0f, 0.0f);
    glDisable(GL_TEXTURE_2D);

    /* row 2 right: viewport and scissor */
    glPushAttrib(GL_VIEWPORT_BIT | GL_SCISSOR_BIT);
    glViewport(0, 0, 128, 128);
    glEnable(GL_SCISSOR_TEST);
    glScissor(90, 80, 20, 20);
    tri(180.0f, 160.0f, 0.0f);
    glPopAttrib();
    put("scissor_test", glIsEnabled(GL_SCISSOR_TEST));
    {
        GLint vp[4];
        glGetIntegerv(GL_VIEWPORT, vp);
        put("viewport_w", vp[2]);
    }
    tri(120.0f, 80.0f, 0.0f);

    /* row 3: current colour, polygon, transform */
    glColor3f(0.9f, 0.9f, 0.1f);
    glPushAttrib(GL_CURRENT_BIT | GL_POLYGON_BIT | GL_TRANSFORM_BIT);
    glColor3f(0.1f, 0.9f, 0.9f);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glMatrixMode(GL_TEXTURE);
    plain_cw(2.0f, 120.0f);
    glPopAttrib();
    put("matrix_mode", geti(GL_MATRIX_MODE));
    put("cull_face", glIsEnabled(GL_CULL_FACE));
    plain_cw(40.0f, 120.0f);

    /* row 3 right: all attributes, pushed and popped inside a display list */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glColor3f(1.0f, 0.0f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    plain_cw(80.0f, 120.0f);
    glPopAttrib();
    glEndList();
    put("depth_after_compile", geti(GL_ATTRIB_STACK_DEPTH));
    glCallList(list);
    put("blend_after_list", glIsEnabled(GL_BLEND));
    plain_cw(120.0f, 120.0f);

    /* overflow and underflow */
    for (i = 0; i < 16; i++)
        glPushAttrib(GL_CURRENT_BIT);
    put("err_before_overflow", glGetError());
    put("depth_full", geti(GL_ATTRIB_STACK_DEPTH));
    glPushAttrib(GL_CURRENT_BIT);
    put("err_overflow", glGetError());
    put("max_depth", geti(GL_MAX_ATTRIB_STACK_DEPTH));
    for (i = 0; i < 16; i++)
        glPopAttrib();
    put("err_before_underflow", glGetError());
    glPopAttrib();
    put("err_underflow", glGetError());
    glBegin(GL_POINTS);
    glPushAttrib(GL_CURRENT_BIT);
    glEnd();
    put("err_push_in_begin", glGetError());

    /* client attributes */
    {
        static const GLfloat va[3][2] = {{150, 180}, {200, 185}, {170, 230}};
        GLint v;
        glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
        glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
        put("client_depth", geti(GL_CLIENT_ATTRIB_STACK_DEPTH));
        glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
        glPixelStorei(GL_PACK_ROW_LENGTH, 17);
        glPopClientAttrib();
        put("unpack_alignment", geti(GL_UNPACK_ALIGNMENT));
        put("pack_row_length", geti(GL_PACK_ROW_LENGTH));

        glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, va);
        glColor3f(1.0f, 1.0f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glPopClientAttrib();
        put("vertex_array_enabled", glIsEnabled(GL_VERTEX_ARRAY));
        glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &v);
        put("vertex_array_size", v);

        glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glNewList(list + 1, GL_COMPILE);
        glPopClientAttrib(); /* executes now, not compiled */
        glEndList();
        put("unpack_alignment_after_list_pop", geti(GL_UNPACK_ALIGNMENT));
        glPopClientAttrib();
        put("client_underflow", glGetError());
        for (i = 0; i < 16; i++)
            glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
        glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
        put("client_overflow", glGetError());
        put("max_client_depth", geti(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH));
    }

    glFinish();
    sgl_text(out, "values", "%s", text);
    sgl_image(out, "scene", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
