/* occlusion_query: GL_SAMPLES_PASSED counts (they must equal Mesa's exactly) for
 * objects partly hidden by depth, masked by stencil, cut by the alpha test, clipped by
 * the view volume, drawn with colour and depth writes off, lines and points; plus the
 * query API's state and errors (glIsQuery, GL_CURRENT_QUERY, GL_QUERY_COUNTER_BITS,
 * ARB aliases, deleting the active query). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 120
#define H 90

static char log_buf[8192];
static size_t log_len;

static void logf_(const char *fmt, unsigned a, unsigned b)
{
    log_len += (size_t)snprintf(log_buf + log_len, sizeof log_buf - log_len, fmt, a, b);
}

static void tri(float x, float y, float s, float z, float alpha)
{
    glBegin(GL_TRIANGLES);
    glColor4f(0.9f, 0.5f, 0.2f, alpha);
    glVertex3f(x, y, z);
    glColor4f(0.2f, 0.9f, 0.3f, 0.0f);
    glVertex3f(x + s, y + 0.13f * s, z);
    glColor4f(0.3f, 0.2f, 0.9f, 1.0f);
    glVertex3f(x + 0.3f * s, y + s, z);
    glEnd();
}

static unsigned count(GLuint q, void (*draw)(void))
{
    GLuint r = 12345;
    GLint avail = 0;
    glBeginQuery(GL_SAMPLES_PASSED, q);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    /* GL_QUERY_RESULT waits for the result; only then is GL_QUERY_RESULT_AVAILABLE
     * deterministic on llvmpipe (right after glEndQuery it depends on thread timing) */
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    glGetQueryObjectiv(q, GL_QUERY_RESULT_AVAILABLE, &avail);
    logf_("avail=%u result=%u\n", (unsigned)avail, r);
    return r;
}

static void d_occluder(void) { glRectf(-0.5f, -0.5f, 0.3f, 0.4f); }
static void d_behind(void) { tri(-0.8f, -0.7f, 1.3f, 0.5f, 1.0f); }
static void d_front(void) { tri(-0.3f, -0.6f, 1.1f, -0.5f, 1.0f); }
static void d_alpha(void)
{
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    tri(-0.9f, -0.9f, 1.7f, -0.8f, 1.0f);
    glDisable(GL_ALPHA_TEST);
}
static void d_stencil(void)
{
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    tri(-0.95f, -0.95f, 1.9f, -0.9f, 1.0f);
    glDisable(GL_STENCIL_TEST);
}
static void d_clipped(void) { tri(0.4f, 0.3f, 2.5f, -0.2f, 1.0f); }
static void d_nowrite(void)
{
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    tri(-0.6f, -0.8f, 1.2f, 0.0f, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
}
static void d_lines_points(void)
{
    int i;
    glBegin(GL_LINES);
    for (i = 0; i < 6; i++) {
        glVertex3f(-0.9f + 0.1f * i, -0.9f, -0.95f);
        glVertex3f(0.8f - 0.05f * i, 0.85f - 0.3f * i, 0.9f);
    }
    glEnd();
    glBegin(GL_POINTS);
    for (i = 0; i < 9; i++)
        glVertex3f(-0.787f + 0.19f * i, 0.013f + 0.1f * (i % 4), -0.5f + 0.2f * (i % 7));
    glEnd();
}
static void d_nothing(void) {}
static void d_culled(void)
{
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    tri(-0.5f, -0.5f, 1.0f, -0.9f, 1.0f);
    glDisable(GL_CULL_FACE);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint q[4] = {0, 0, 0, 0}, r;
    GLint v = -1, bits = -1;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    glGenQueries(3, q);
    logf_("gen %u %u\n", q[0], q[1]);
    logf_("isQuery before begin=%u err=0x%x\n", glIsQuery(q[0]), glGetError());
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &r);
    logf_("result of unbegun: err=0x%x %u\n", glGetError(), 0);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &bits);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
    logf_("counter_bits=%d current=%d\n", (unsigned)bits, (unsigned)v);

    /* an occluder writes depth 0 and stencil 1 */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor3f(0.5f, 0.5f, 0.5f);
    count(q[0], d_occluder);
    glDisable(GL_STENCIL_TEST);
    logf_("isQuery after=%u %u\n", glIsQuery(q[0]), glIsQuery(q[1]));
    count(q[1], d_behind);
    count(q[1], d_front);
    count(q[2], d_alpha);
    count(q[0], d_stencil);
    count(q[1], d_clipped);
    count(q[2], d_nowrite);
    count(q[0], d_lines_points);
    count(q[1], d_nothing);
    count(q[2], d_culled);

    /* state and errors */
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
    logf_("current while active=%u err=0x%x\n", (unsigned)v, glGetError());
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    logf_("begin while active: 0x%x %u\n", glGetError(), 0);
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &r);
    logf_("result of active: 0x%x %u\n", glGetError(), 0);
    d_front();
    glEndQuery(GL_SAMPLES_PASSED);
    glEndQuery(GL_SAMPLES_PASSED);
    logf_("end twice: 0x%x %u\n", glGetError(), 0);
    glBeginQuery(GL_SAMPLES_PASSED, 0);
    logf_("begin 0: 0x%x %u\n", glGetError(), 0);
    glBeginQuery(GL_TEXTURE_2D, q[0]);
    logf_("begin bad target: 0x%x %u\n", glGetError(), 0);
    glEndQuery(GL_TEXTURE_2D);
    logf_("end bad target: 0x%x %u\n", glGetError(), 0);
    glGetQueryiv(GL_TEXTURE_2D, GL_CURRENT_QUERY, &v);
    logf_("getqueryiv bad target: 0x%x %u\n", glGetError(), 0);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &v);
    logf_("getqueryiv bad pname: 0x%x %u\n", glGetError(), 0);
    glGetQueryObjectiv(q[0], GL_CURRENT_QUERY, &v);
    logf_("getqueryobject bad pname: 0x%x %u\n", glGetError(), 0);
    glGetQueryObjectiv(777, GL_QUERY_RESULT, &v);
    logf_("getqueryobject unknown: 0x%x %u\n", glGetError(), 0);
    glGetQueryObjectiv(0, GL_QUERY_RESULT, &v);
    logf_("getqueryobject 0: 0x%x %u\n", glGetError(), 0);
    glGenQueries(-1, q);
    logf_("gen -1: 0x%x %u\n", glGetError(), 0);
    glDeleteQueries(-1, q);
    logf_("delete -1: 0x%x %u\n", glGetError(), 0);
    glBegin(GL_TRIANGLES);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glEnd();
    logf_("begin inside glBegin: 0x%x %u\n", glGetError(), 0);
    /* a name never generated works in the compatibility profile */
    glBeginQueryARB(GL_SAMPLES_PASSED_ARB, 4242);
    d_front();
    glEndQueryARB(GL_SAMPLES_PASSED_ARB);
    glGetQueryObjectuivARB(4242, GL_QUERY_RESULT_ARB, &r);
    logf_("ungenerated name: err=0x%x result=%u\n", glGetError(), r);
    logf_("isQueryARB=%u %u\n", glIsQueryARB(4242), glIsQuery(999));
    /* deleting the active query ends it */
    glBeginQuery(GL_SAMPLES_PASSED, q[2]);
    glDeleteQueriesARB(1, &q[2]);
    glGetQueryivARB(GL_SAMPLES_PASSED, GL_CURRENT_QUERY_ARB, &v);
    logf_("after deleting active: current=%u err=0x%x\n", (unsigned)v, glGetError());
    glEndQuery(GL_SAMPLES_PASSED);
    logf_("end after delete: 0x%x isQuery=%u\n", glGetError(), glIsQuery(q[2]));
    glBeginQuery(GL_SAMPLES_PASSED, q[2]);
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectuiv(q[2], GL_QUERY_RESULT, &r);
    glGetQueryObjectivARB(q[2], GL_QUERY_RESULT_AVAILABLE_ARB, &v);
    logf_("reuse deleted name: avail=%u err=0x%x\n", (unsigned)v, glGetError());
    glDeleteQueries(3, q);
    glDeleteQueries(1, q);
    logf_("delete twice: 0x%x isQuery=%u\n", glGetError(), glIsQuery(q[0]));

    glFinish();
    sgl_text(out, "log", "%s", log_buf);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
