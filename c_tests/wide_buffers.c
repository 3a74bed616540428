/* wide_buffers: lit, smooth-shaded, fogged, textured and blended geometry rendered
 * into OSMesa buffers of GL_UNSIGNED_SHORT and GL_FLOAT (OSMESA_RGBA, OSMESA_BGRA and
 * OSMESA_RGB), dumped at full precision: the raw buffer after glFinish, and glReadPixels
 * of GL_FLOAT and GL_UNSIGNED_SHORT from it. Mesa renders these buffers as
 * R16G16B16A16_UNORM / R32G32B32A32_FLOAT (R32G32B32_FLOAT) and blends at that
 * precision (docs/llvmpipe-rules.md §23). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 80
#define H 64
#define TS 8

static void scene(void)
{
    static const GLfloat pos[4] = {0.4f, 0.7f, 1.0f, 0.0f};
    static const GLfloat diff[4] = {0.9f, 0.7f, 0.4f, 0.8f};
    static const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    static const GLfloat fog[4] = {0.3f, 0.35f, 0.5f, 1.0f};
    GLubyte tex[TS * TS * 4];
    GLuint name;
    int i, j;
    for (i = 0; i < TS * TS; i++) {
        int x = i % TS, y = i / TS;
        tex[4 * i + 0] = (GLubyte)(x * 33 + 7);
        tex[4 * i + 1] = (GLubyte)(y * 29 + 11);
        tex[4 * i + 2] = (GLubyte)((x ^ y) * 30 + 3);
        tex[4 * i + 3] = (GLubyte)(128 + x * 15);
    }
    glViewport(0, 0, W, H);
    glClearColor(0.12f, 0.2f, 0.35f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(25.0f, 1.0f, 0.3f, 0.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 5.0f);
    glFogfv(GL_FOG_COLOR, fog);
    /* a lit, fogged bumpy sheet */
    for (j = 0; j < 8; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 10; i++) {
            int k;
            for (k = 0; k < 2; k++) {
                float u = -1.0f + 0.2f * i, v = -1.0f + 0.25f * (j + k);
                float z = 0.2f * sinf(2.0f * u) * cosf(2.0f * v);
                glNormal3f(-0.4f * cosf(2.0f * u) * cosf(2.0f * v),
                           0.4f * sinf(2.0f * u) * sinf(2.0f * v), 1.0f);
                glVertex3f(u, v, z);
            }
        }
        glEnd();
    }
    glDisable(GL_LIGHTING);
    /* a textured, fogged, blended quad (MODULATE with a smooth colour) */
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.9f, 0.8f, 0.9f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-0.7f, -0.6f, 0.35f);
    glColor4f(0.7f, 1.0f, 0.9f, 0.7f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.1f, -0.6f, 0.35f);
    glColor4f(0.9f, 0.8f, 1.0f, 1.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex3f(0.1f, 0.2f, 0.35f);
    glColor4f(1.0f, 1.0f, 1.0f, 0.8f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex3f(-0.7f, 0.2f, 0.35f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    /* blended, smooth-shaded triangles over it, then additive ones */
    glDisable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++) {
        float x = -0.9f + 0.3f * i;
        glColor4f(1.0f, 0.1f * i, 0.2f, 0.35f);
        glVertex3f(x, -0.8f, 0.3f);
        glColor4f(0.1f, 0.9f, 0.15f * i, 0.6f);
        glVertex3f(x + 0.5f, -0.5f, 0.3f);
        glColor4f(0.2f, 0.3f, 1.0f, 0.8f);
        glVertex3f(x + 0.1f, 0.7f, 0.3f);
    }
    glEnd();
    glBlendFunc(GL_ONE, GL_ONE);
    glBegin(GL_TRIANGLES);
    glColor4f(0.3f, 0.1f, 0.05f, 0.2f);
    glVertex3f(-0.2f, -0.2f, 0.0f);
    glColor4f(0.05f, 0.3f, 0.1f, 0.1f);
    glVertex3f(0.8f, 0.0f, 0.0f);
    glColor4f(0.1f, 0.05f, 0.4f, 0.3f);
    glVertex3f(0.3f, 0.8f, 0.0f);
    glEnd();
    glDisable(GL_BLEND);
    glDeleteTextures(1, &name);
}

static void run(FILE *out, const char *name, GLenum format, GLenum type, int channels)
{
    OSMesaContext ctx = OSMesaCreateContextExt(format, 24, 0, 0, NULL);
    int bytes = type == GL_UNSIGNED_SHORT ? 2 : 4;
    size_t n = (size_t)W * H * channels;
    unsigned char *buf = malloc(n * bytes);
    float *rf = malloc((size_t)W * H * 4 * sizeof(float));
    unsigned short *rs = malloc((size_t)W * H * 4 * sizeof(unsigned short));
    char label[64];
    SGL_CHECK(ctx && buf && rf && rs);
    memset(buf, 0x5A, n * bytes);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, type, W, H));
    scene();
    glFinish();
    snprintf(label, sizeof label, "%s_buffer", name);
    sgl_data(out, label, n * bytes, buf);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, rf);
    snprintf(label, sizeof label, "%s_read_float", name);
    sgl_data(out, label, (size_t)W * H * 4 * sizeof(float), rf);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_SHORT, rs);
    snprintf(label, sizeof label, "%s_read_ushort", name);
    sgl_data(out, label, (size_t)W * H * 4 * sizeof(unsigned short), rs);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rs);
    snprintf(label, sizeof label, "%s_read_ubyte", name);
    sgl_data(out, label, (size_t)W * H * 4, rs);
    sgl_text(out, "err", "%s err=0x%x\n", name, glGetError());
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(rf);
    free(rs);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    run(out, "rgba_ushort", OSMESA_RGBA, GL_UNSIGNED_SHORT, 4);
    run(out, "rgba_float", OSMESA_RGBA, GL_FLOAT, 4);
    run(out, "bgra_ushort", OSMESA_BGRA, GL_UNSIGNED_SHORT, 4);
    run(out, "rgb_float", OSMESA_RGB, GL_FLOAT, 3);
    sgl_close(out);
    return 0;
}
