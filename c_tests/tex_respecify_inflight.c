/* tex_respecify_inflight: textured draws followed at once by calls that change
 * or read what the draw uses.  With threads on, softgl leaves the last batch
 * of a glBegin/glEnd draw drawing on its thread pool when glEnd (of a strip)
 * returns, and the next glBegin/glEnd draw takes it back; every other call
 * waits for it first.  So a call that changes a texture image the batch
 * samples (glTexSubImage2D, glTexImage2D, glCopyTexSubImage2D,
 * glGenerateMipmap, glDeleteTextures), reads the framebuffer (glReadPixels)
 * or switches it (glBindFramebuffer) must see it drawn.  Each draw covers the
 * whole 512x512 buffer with a grid of N triangle strips and blends onto what
 * the earlier draws left, so a batch that sampled the re-specified texels
 * would change the image.  Run with threads on, as every scene is, and
 * compared with OSMesa. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 512
#define H 512
#define N 32 /* grid cells a side: 2 * N * N triangles */
#define T 64 /* texture size */

static GLfloat pos[N * N * 6][2];
static GLfloat tc[N * N * 6][2];

/* The grid of triangles over the viewport, texture coordinates 0..2 (so
 * REPEAT shows the texture twice). */
static void make_grid(void)
{
    int i, j, k = 0;
    for (j = 0; j < N; j++)
        for (i = 0; i < N; i++) {
            static const int cx[6] = {0, 1, 1, 0, 1, 0};
            static const int cy[6] = {0, 0, 1, 0, 1, 1};
            int v;
            for (v = 0; v < 6; v++, k++) {
                float u = (float)(i + cx[v]) / N, w = (float)(j + cy[v]) / N;
                pos[k][0] = -1.0f + 2.0f * u;
                pos[k][1] = -1.0f + 2.0f * w;
                tc[k][0] = 2.0f * u;
                tc[k][1] = 2.0f * w;
            }
        }
}

/* The grid as one GL_TRIANGLE_STRIP per row of cells, each drawn (and left
 * on the pool) at its glEnd. */
static void draw_grid(void)
{
    int i, j;
    for (j = 0; j < N; j++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= N; i++) {
            float u = (float)i / N;
            glTexCoord2f(2.0f * u, 2.0f * (float)(j + 1) / N);
            glVertex2f(-1.0f + 2.0f * u, -1.0f + 2.0f * (float)(j + 1) / N);
            glTexCoord2f(2.0f * u, 2.0f * (float)j / N);
            glVertex2f(-1.0f + 2.0f * u, -1.0f + 2.0f * (float)j / N);
        }
        glEnd();
    }
}

/* A texture of T x T texels, every texel a function of (x, y, seed). */
static unsigned char *pattern(int seed)
{
    unsigned char *p = malloc(T * T * 4);
    int x, y;
    SGL_CHECK(p != NULL);
    for (y = 0; y < T; y++)
        for (x = 0; x < T; x++) {
            unsigned char *t = p + 4 * (y * T + x);
            t[0] = (unsigned char)(x * 4 + seed * 37);
            t[1] = (unsigned char)(y * 4 + seed * 91);
            t[2] = (unsigned char)(((x / 8 + y / 8) & 1) ? 200 - seed * 20 : 40 + seed * 30);
            t[3] = 255;
        }
    return p;
}

static void tex_params(void)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

int main(int argc, char **argv)
{
    unsigned char *buf, *a = pattern(0), *b = pattern(1), *c = pattern(2);
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    FILE *out = sgl_open(argc, argv);
    GLuint tex[3], fbo, fbtex;
    static unsigned char pix[W * H * 4];

    make_grid();
    glViewport(0, 0, W, H);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glTexCoordPointer(2, GL_FLOAT, 0, tc);
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    tex_params();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, a);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    tex_params();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, b);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

    /* 1. texture 0, then its texels replaced right after the draw */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
    draw_grid();
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, T, T, GL_RGBA, GL_UNSIGNED_BYTE, c);
    /* 2. blended over it with the new texels, through state calls only */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.25f, 0.125f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    draw_grid();
    /* 3. the same texture re-specified at another size */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, b);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T / 2, T / 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, a);
    glColor4f(0.8f, 1.0f, 0.6f, 0.4f);
    draw_grid();
    /* 4. another texture bound between draws (state only), then the first
     * one deleted right after a draw that samples it */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glRotatef(7.0f, 0.0f, 0.0f, 1.0f);
    draw_grid();
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    draw_grid();
    glDeleteTextures(1, &tex[0]);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    tex_params();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
    glColor4f(1.0f, 0.7f, 0.9f, 0.5f);
    draw_grid();
    /* 5. the framebuffer copied into the texture the draw samples */
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 100, 100, T, T);
    glLoadIdentity();
    glScalef(0.9f, 0.9f, 1.0f);
    draw_grid();
    /* 6. mipmaps made for the texture a draw just sampled */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glGenerateMipmap(GL_TEXTURE_2D);
    glScalef(0.5f, 0.5f, 1.0f);
    draw_grid();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pix);
    sgl_image(out, "readback", W, H, 4, "RGBA", W * 4, 1, pix);
    /* 7. a texture drawn into through a framebuffer object right after the
     * window's draw sampled it, then sampled again from the window */
    glGenTextures(1, &fbtex);
    glBindTexture(GL_TEXTURE_2D, fbtex);
    tex_params();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, b);
    glLoadIdentity();
    draw_grid();
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, fbtex, 0);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    glViewport(0, 0, T, T);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_BLEND);
    glColor4f(0.9f, 0.3f, 0.1f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 6 * N * N / 2);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, W, H);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
    draw_grid();
    glFinish();
    sgl_image(out, "final", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(a);
    free(b);
    free(c);
    return 0;
}
