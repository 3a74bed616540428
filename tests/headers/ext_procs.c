/*
 * A program written the way glad, VTK and most tutorials load OpenGL 1.2+ and extension
 * functions: declare pointers of glext.h's PFNGL...PROC types and fill them with
 * OSMesaGetProcAddress. Uses extension tokens real programs use. tests/headers/mesa.rs builds it
 * against softgl's headers only and against Mesa's, runs both and compares the output.
 *
 * Draws into a framebuffer object with glClipControl's upper-left origin (so a quad in the
 * lower half of clip space lands in the upper half of the image), blits that to the
 * window, reads two pixels back and prints them with some multisample state.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#if GL_TEXTURE_CUBE_MAP_EXT != 0x8513 || GL_MULTISAMPLE_ARB != 0x809D
#error "GL_TEXTURE_CUBE_MAP_EXT / GL_MULTISAMPLE_ARB"
#endif
#if GL_SAMPLE_BUFFERS_ARB != 0x80A8 || GL_SAMPLES_ARB != 0x80A9 || GL_POINT_SPRITE_ARB != 0x8861
#error "GL_SAMPLE_BUFFERS_ARB / GL_SAMPLES_ARB / GL_POINT_SPRITE_ARB"
#endif

#define W 32
#define H 32

static PFNGLGENFRAMEBUFFERSPROC gen_framebuffers;
static PFNGLBINDFRAMEBUFFERPROC bind_framebuffer;
static PFNGLDELETEFRAMEBUFFERSPROC delete_framebuffers;
static PFNGLGENRENDERBUFFERSPROC gen_renderbuffers;
static PFNGLBINDRENDERBUFFERPROC bind_renderbuffer;
static PFNGLDELETERENDERBUFFERSPROC delete_renderbuffers;
static PFNGLRENDERBUFFERSTORAGEPROC renderbuffer_storage;
static PFNGLFRAMEBUFFERRENDERBUFFERPROC framebuffer_renderbuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC check_framebuffer_status;
static PFNGLBLITFRAMEBUFFERPROC blit_framebuffer;
static PFNGLACTIVETEXTUREPROC active_texture;
static PFNGLCLIPCONTROLPROC clip_control;

/* Looks a function up; a missing one ends the program. */
static OSMESAproc load(const char *name)
{
    OSMESAproc p = OSMesaGetProcAddress(name);
    if (p == NULL) {
        printf("missing %s\n", name);
        exit(3);
    }
    return p;
}

static void load_all(void)
{
    gen_framebuffers = (PFNGLGENFRAMEBUFFERSPROC)load("glGenFramebuffers");
    bind_framebuffer = (PFNGLBINDFRAMEBUFFERPROC)load("glBindFramebuffer");
    delete_framebuffers = (PFNGLDELETEFRAMEBUFFERSPROC)load("glDeleteFramebuffers");
    gen_renderbuffers = (PFNGLGENRENDERBUFFERSPROC)load("glGenRenderbuffers");
    bind_renderbuffer = (PFNGLBINDRENDERBUFFERPROC)load("glBindRenderbuffer");
    delete_renderbuffers = (PFNGLDELETERENDERBUFFERSPROC)load("glDeleteRenderbuffers");
    renderbuffer_storage = (PFNGLRENDERBUFFERSTORAGEPROC)load("glRenderbufferStorage");
    framebuffer_renderbuffer = (PFNGLFRAMEBUFFERRENDERBUFFERPROC)load("glFramebufferRenderbuffer");
    check_framebuffer_status = (PFNGLCHECKFRAMEBUFFERSTATUSPROC)load("glCheckFramebufferStatus");
    blit_framebuffer = (PFNGLBLITFRAMEBUFFERPROC)load("glBlitFramebuffer");
    active_texture = (PFNGLACTIVETEXTUREPROC)load("glActiveTexture");
    clip_control = (PFNGLCLIPCONTROLPROC)load("glClipControl");
}

static void print_pixel(const char *what, int x, int y)
{
    GLubyte p[4] = { 0, 0, 0, 0 };
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    printf("%s (%d,%d): %u %u %u %u\n", what, x, y, p[0], p[1], p[2], p[3]);
}

int main(void)
{
    GLubyte *window = (GLubyte *)calloc(W * H, 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLuint fbo = 0, rb = 0, tex = 0;
    GLint sample_buffers = -1, samples = -1, cube = -1;
    GLenum status;
    if (window == NULL || ctx == NULL || !OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H))
        return 2;
    load_all();

    gen_framebuffers(1, &fbo);
    gen_renderbuffers(1, &rb);
    bind_renderbuffer(GL_RENDERBUFFER, rb);
    renderbuffer_storage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    bind_framebuffer(GL_FRAMEBUFFER, fbo);
    framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    status = check_framebuffer_status(GL_FRAMEBUFFER);
    printf("framebuffer status 0x%04X\n", status);

    glViewport(0, 0, W, H);
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    clip_control(GL_UPPER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glColor3f(1.0f, 0.0f, 0.0f);
    glBegin(GL_QUADS); /* the lower half of clip space */
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(1.0f, 0.0f);
    glVertex2f(-1.0f, 0.0f);
    glEnd();
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    print_pixel("fbo top", W / 2, H * 3 / 4);
    print_pixel("fbo bottom", W / 2, H / 4);

    bind_framebuffer(GL_READ_FRAMEBUFFER, fbo);
    bind_framebuffer(GL_DRAW_FRAMEBUFFER, 0);
    blit_framebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    bind_framebuffer(GL_FRAMEBUFFER, 0);
    print_pixel("window top", W / 2, H * 3 / 4);
    print_pixel("window bottom", W / 2, H / 4);

    active_texture(GL_TEXTURE1);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP_EXT, tex);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP_EXT, &cube);
    active_texture(GL_TEXTURE0);
    glGetIntegerv(GL_SAMPLE_BUFFERS_ARB, &sample_buffers);
    glGetIntegerv(GL_SAMPLES_ARB, &samples);
    printf("cube map bound on unit 1: %d\n", cube == (GLint)tex);
    printf("sample buffers %d, samples %d, multisample enabled %d\n", sample_buffers, samples,
           glIsEnabled(GL_MULTISAMPLE_ARB));
    printf("error 0x%04X\n", glGetError());

    delete_framebuffers(1, &fbo);
    delete_renderbuffers(1, &rb);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(window);
    return 0;
}
