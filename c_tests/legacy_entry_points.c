/* legacy_entry_points: the GL 1.0-1.5 functions an RGBA OSMesa program can
 * call but that draw nothing of their own: colour-index state (glIndex*,
 * glIndexMask, glClearIndex, glIndexPointer and the index array), the
 * ARB_imaging subset (colour tables, convolution, histogram, minmax),
 * compressed-texture calls without a compressed format, glSampleCoverage and
 * the multisample enables, glDrawBuffer/glReadBuffer on a single-buffered
 * OSMesa framebuffer (GL_NONE draws nothing), the EXT_vertex_array pointer
 * calls (the count argument is ignored) and the evaluator grid queries.
 * Each call's error and the state it leaves are printed; the image shows
 * what was drawn through the EXT pointers and with the draw buffer off. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48

static FILE *out;
static char log_buf[4000];
static int log_len;

static void lg(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_len += vsnprintf(log_buf + log_len, sizeof log_buf - log_len, fmt, ap);
    va_end(ap);
}

static void flush_log(const char *name)
{
    sgl_text(out, name, "%s", log_buf);
    log_len = 0;
    log_buf[0] = 0;
}

#define ERR(label) lg(label " err=0x%04x\n", glGetError())

static void getf(const char *name, GLenum pname, int n)
{
    GLfloat f[16];
    GLint iv[16];
    int k;
    for (k = 0; k < 16; k++) {
        f[k] = -7.0f;
        iv[k] = -7;
    }
    glGetFloatv(pname, f);
    glGetIntegerv(pname, iv);
    lg("%s err=0x%04x:", name,
                        glGetError());
    for (k = 0; k < n; k++)
        lg(" %.9g/%d", f[k], iv[k]);
    lg("\n");
}

static void index_state(void)
{
    static const GLfloat idx[4] = {1.0f, 2.0f, 3.0f, 4.0f};
    static const GLshort tri[6] = {2, 2, 20, 2, 2, 20};
    void *p = NULL;
    GLuint list;

    getf("CURRENT_INDEX initial", GL_CURRENT_INDEX, 1);
    getf("INDEX_WRITEMASK initial", GL_INDEX_WRITEMASK, 1);
    getf("INDEX_CLEAR_VALUE initial", GL_INDEX_CLEAR_VALUE, 1);
    glIndexf(2.75f);
    getf("CURRENT_INDEX f", GL_CURRENT_INDEX, 1);
    glIndexi(-5);
    getf("CURRENT_INDEX i", GL_CURRENT_INDEX, 1);
    glIndexub(200);
    getf("CURRENT_INDEX ub", GL_CURRENT_INDEX, 1);
    {
        GLdouble d = 9.5;
        GLshort s = 300;
        glIndexdv(&d);
        getf("CURRENT_INDEX dv", GL_CURRENT_INDEX, 1);
        glIndexsv(&s);
        getf("CURRENT_INDEX sv", GL_CURRENT_INDEX, 1);
    }
    glIndexMask(0x5a);
    getf("INDEX_WRITEMASK set", GL_INDEX_WRITEMASK, 1);
    glClearIndex(3.25f);
    getf("INDEX_CLEAR_VALUE set", GL_INDEX_CLEAR_VALUE, 1);

    /* push/pop: current index in CURRENT_BIT, mask and clear index in
     * COLOR_BUFFER_BIT */
    glPushAttrib(GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT);
    glIndexf(1.0f);
    glIndexMask(1);
    glClearIndex(0.5f);
    glPopAttrib();
    getf("CURRENT_INDEX popped", GL_CURRENT_INDEX, 1);
    getf("INDEX_WRITEMASK popped", GL_INDEX_WRITEMASK, 1);
    getf("INDEX_CLEAR_VALUE popped", GL_INDEX_CLEAR_VALUE, 1);

    /* display lists compile glIndex and glIndexMask (glClearIndex too, but
     * Mesa 22.3's list replays the float's bits as an integer) */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glIndexf(6.5f);
    glIndexMask(0x33);
    glEndList();
    getf("CURRENT_INDEX after compile", GL_CURRENT_INDEX, 1);
    glCallList(list);
    getf("CURRENT_INDEX after call", GL_CURRENT_INDEX, 1);
    getf("INDEX_WRITEMASK after call", GL_INDEX_WRITEMASK, 1);
    glDeleteLists(list, 1);

    /* the index array */
    glIndexPointer(GL_FLOAT, 0, idx);
    ERR("IndexPointer float");
    glIndexPointer(GL_BYTE, 0, idx);
    ERR("IndexPointer byte");
    glIndexPointer(GL_UNSIGNED_BYTE, -4, idx);
    ERR("IndexPointer stride -4");
    glIndexPointer(GL_SHORT, 6, idx);
    ERR("IndexPointer short 6");
    getf("INDEX_ARRAY_TYPE", GL_INDEX_ARRAY_TYPE, 1);
    getf("INDEX_ARRAY_STRIDE", GL_INDEX_ARRAY_STRIDE, 1);
    getf("INDEX_ARRAY_BUFFER_BINDING", GL_INDEX_ARRAY_BUFFER_BINDING, 1);
    glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
    lg("INDEX_ARRAY_POINTER matches=%d err=0x%04x\n", p == (void *)idx,
          glGetError());
    lg("INDEX_ARRAY enabled=%d\n", glIsEnabled(GL_INDEX_ARRAY));
    glEnableClientState(GL_INDEX_ARRAY);
    ERR("EnableClientState INDEX_ARRAY");
    lg("INDEX_ARRAY enabled=%d\n", glIsEnabled(GL_INDEX_ARRAY));
    getf("INDEX_ARRAY get", GL_INDEX_ARRAY, 1);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glIndexPointer(GL_INT, 0, NULL);
    glDisableClientState(GL_INDEX_ARRAY);
    glPopClientAttrib();
    getf("INDEX_ARRAY_TYPE popped", GL_INDEX_ARRAY_TYPE, 1);
    lg("INDEX_ARRAY enabled popped=%d\n", glIsEnabled(GL_INDEX_ARRAY));
    /* an index array enabled while drawing changes nothing in RGBA mode */
    glIndexPointer(GL_FLOAT, 0, idx);
    glVertexPointer(2, GL_SHORT, 0, tri);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(0.2f, 0.9f, 0.4f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ERR("DrawArrays with index array");
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_INDEX_ARRAY);
    glBegin(GL_POINTS);
    glIndexi(3);
    glEnd();
    ERR("glIndex in Begin/End");
    flush_log("index");
}

static void imaging(void)
{
    GLubyte tab[64];
    GLfloat fv[4] = {0, 0, 0, 0};
    GLint iv[4] = {0, 0, 0, 0};
    memset(tab, 0x80, sizeof tab);
    glColorTable(GL_COLOR_TABLE, GL_RGBA, 4, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("ColorTable");
    glColorSubTable(GL_COLOR_TABLE, 0, 2, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("ColorSubTable");
    glColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE, fv);
    ERR("ColorTableParameterfv");
    glColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_BIAS, iv);
    ERR("ColorTableParameteriv");
    glCopyColorTable(GL_COLOR_TABLE, GL_RGBA, 0, 0, 4);
    ERR("CopyColorTable");
    glCopyColorSubTable(GL_COLOR_TABLE, 0, 0, 0, 4);
    ERR("CopyColorSubTable");
    glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("GetColorTable");
    glGetColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, fv);
    ERR("GetColorTableParameterfv");
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, iv);
    ERR("GetColorTableParameteriv");
    glConvolutionFilter1D(GL_CONVOLUTION_1D, GL_RGBA, 3, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("ConvolutionFilter1D");
    glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("ConvolutionFilter2D");
    glConvolutionParameterf(GL_CONVOLUTION_1D, GL_CONVOLUTION_BORDER_MODE, 1.0f);
    ERR("ConvolutionParameterf");
    glConvolutionParameterfv(GL_CONVOLUTION_1D, GL_CONVOLUTION_FILTER_SCALE, fv);
    ERR("ConvolutionParameterfv");
    glConvolutionParameteri(GL_CONVOLUTION_1D, GL_CONVOLUTION_BORDER_MODE, 1);
    ERR("ConvolutionParameteri");
    glConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_FILTER_BIAS, iv);
    ERR("ConvolutionParameteriv");
    glCopyConvolutionFilter1D(GL_CONVOLUTION_1D, GL_RGBA, 0, 0, 3);
    ERR("CopyConvolutionFilter1D");
    glCopyConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA, 0, 0, 2, 2);
    ERR("CopyConvolutionFilter2D");
    glGetConvolutionFilter(GL_CONVOLUTION_1D, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("GetConvolutionFilter");
    glGetConvolutionParameterfv(GL_CONVOLUTION_1D, GL_CONVOLUTION_WIDTH, fv);
    ERR("GetConvolutionParameterfv");
    glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_WIDTH, iv);
    ERR("GetConvolutionParameteriv");
    glSeparableFilter2D(GL_SEPARABLE_2D, GL_RGBA, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, tab, tab);
    ERR("SeparableFilter2D");
    glGetSeparableFilter(GL_SEPARABLE_2D, GL_RGBA, GL_UNSIGNED_BYTE, tab, tab, NULL);
    ERR("GetSeparableFilter");
    glHistogram(GL_HISTOGRAM, 16, GL_RGBA, GL_FALSE);
    ERR("Histogram");
    glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("GetHistogram");
    glGetHistogramParameterfv(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH, fv);
    ERR("GetHistogramParameterfv");
    glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH, iv);
    ERR("GetHistogramParameteriv");
    glResetHistogram(GL_HISTOGRAM);
    ERR("ResetHistogram");
    glMinmax(GL_MINMAX, GL_RGBA, GL_FALSE);
    ERR("Minmax");
    glGetMinmax(GL_MINMAX, GL_FALSE, GL_RGBA, GL_UNSIGNED_BYTE, tab);
    ERR("GetMinmax");
    glGetMinmaxParameterfv(GL_MINMAX, GL_MINMAX_FORMAT, fv);
    ERR("GetMinmaxParameterfv");
    glGetMinmaxParameteriv(GL_MINMAX, GL_MINMAX_FORMAT, iv);
    ERR("GetMinmaxParameteriv");
    glResetMinmax(GL_MINMAX);
    ERR("ResetMinmax");
    lg("tab untouched=%d iv0=%d fv0=%g\n", tab[0] == 0x80 && tab[63] == 0x80, iv[0], fv[0]);
    glEnable(GL_COLOR_TABLE);
    ERR("Enable COLOR_TABLE");
    glEnable(GL_HISTOGRAM);
    ERR("Enable HISTOGRAM");
    flush_log("imaging");
}

static void compressed(void)
{
    GLubyte data[256];
    GLuint tex;
    memset(data, 0x11, sizeof data);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 64, data);
    ERR("CompressedTexImage2D RGBA");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, -1, data);
    ERR("CompressedTexImage2D imageSize -1");
    glCompressedTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 4, 0, 16, data);
    ERR("CompressedTexImage1D RGB");
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 4, 4, 4, 0, 64, data);
    ERR("CompressedTexImage3D LUMINANCE");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 4, 4, 0, 64, data);
    ERR("CompressedTexImage2D generic COMPRESSED_RGBA");
    glCompressedTexImage2DARB(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, 64, data);
    ERR("CompressedTexImage2DARB RGBA8");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    ERR("TexImage2D");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, 64, data);
    ERR("CompressedTexSubImage2D RGBA");
    glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, GL_RGB, 16, data);
    ERR("CompressedTexSubImage1D RGB");
    glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 4, GL_RGBA, 64, data);
    ERR("CompressedTexSubImage3D RGBA");
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, data);
    ERR("GetCompressedTexImage uncompressed");
    glGetCompressedTexImageARB(GL_TEXTURE_2D, 0, data);
    ERR("GetCompressedTexImageARB uncompressed");
    glGetCompressedTexImage(GL_TEXTURE_2D, 99, data);
    ERR("GetCompressedTexImage level 99");
    glCompressedTexSubImage2DARB(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGB, 64, data);
    ERR("CompressedTexSubImage2DARB RGB");
    glCompressedTexImage1DARB(GL_TEXTURE_1D, 0, GL_RGB, 4, 0, 16, data);
    ERR("CompressedTexImage1DARB");
    glCompressedTexImage3DARB(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, 16, data);
    ERR("CompressedTexImage3DARB");
    glCompressedTexSubImage1DARB(GL_TEXTURE_1D, 0, 0, 4, GL_RGB, 16, data);
    ERR("CompressedTexSubImage1DARB");
    glCompressedTexSubImage3DARB(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 4, GL_RGBA, 64, data);
    ERR("CompressedTexSubImage3DARB");
    {
        GLint v = -7;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v);
        lg("TEXTURE_COMPRESSED=%d err=0x%04x\n", v, glGetError());
    }
    lg("data untouched=%d\n", data[0] == 0x11 && data[255] == 0x11);
    glDeleteTextures(1, &tex);
    flush_log("compressed");
}

static void multisample(void)
{
    getf("SAMPLE_COVERAGE_VALUE initial", GL_SAMPLE_COVERAGE_VALUE, 1);
    getf("SAMPLE_COVERAGE_INVERT initial", GL_SAMPLE_COVERAGE_INVERT, 1);
    getf("SAMPLE_BUFFERS", GL_SAMPLE_BUFFERS, 1);
    getf("SAMPLES", GL_SAMPLES, 1);
    lg("MULTISAMPLE=%d SAMPLE_COVERAGE=%d ALPHA_TO_COVERAGE=%d ALPHA_TO_ONE=%d\n",
          glIsEnabled(GL_MULTISAMPLE), glIsEnabled(GL_SAMPLE_COVERAGE),
          glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE));
    glSampleCoverage(0.3f, GL_TRUE);
    ERR("SampleCoverage");
    getf("SAMPLE_COVERAGE_VALUE set", GL_SAMPLE_COVERAGE_VALUE, 1);
    getf("SAMPLE_COVERAGE_INVERT set", GL_SAMPLE_COVERAGE_INVERT, 1);
    glSampleCoverageARB(1.75f, GL_FALSE);
    ERR("SampleCoverageARB 1.75");
    getf("SAMPLE_COVERAGE_VALUE clamped", GL_SAMPLE_COVERAGE_VALUE, 1);
    glSampleCoverage(-2.0f, GL_TRUE);
    ERR("SampleCoverage -2");
    getf("SAMPLE_COVERAGE_VALUE neg", GL_SAMPLE_COVERAGE_VALUE, 1);
    getf("SAMPLE_COVERAGE_INVERT true", GL_SAMPLE_COVERAGE_INVERT, 1);
    glPushAttrib(GL_MULTISAMPLE_BIT);
    glSampleCoverage(0.6f, GL_FALSE);
    glDisable(GL_MULTISAMPLE);
    glEnable(GL_SAMPLE_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    ERR("multisample enables");
    lg("MULTISAMPLE=%d SAMPLE_COVERAGE=%d ALPHA_TO_COVERAGE=%d ALPHA_TO_ONE=%d\n",
          glIsEnabled(GL_MULTISAMPLE), glIsEnabled(GL_SAMPLE_COVERAGE),
          glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE));
    getf("SAMPLE_COVERAGE get", GL_SAMPLE_COVERAGE, 1);
    getf("MULTISAMPLE get", GL_MULTISAMPLE, 1);
    glPopAttrib();
    lg("popped MULTISAMPLE=%d SAMPLE_COVERAGE=%d ALPHA_TO_COVERAGE=%d ALPHA_TO_ONE=%d\n",
          glIsEnabled(GL_MULTISAMPLE), glIsEnabled(GL_SAMPLE_COVERAGE),
          glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE));
    getf("SAMPLE_COVERAGE_VALUE popped", GL_SAMPLE_COVERAGE_VALUE, 1);
    flush_log("multisample");
}

static void buffers(unsigned char *img)
{
    static const GLenum draw_enums[] = {GL_FRONT, GL_BACK, GL_LEFT, GL_RIGHT, GL_FRONT_LEFT,
                                        GL_FRONT_RIGHT, GL_BACK_LEFT, GL_FRONT_AND_BACK,
                                        GL_AUX0, GL_AUX3, GL_NONE, GL_TEXTURE_2D};
    static const char *draw_names[] = {"FRONT", "BACK", "LEFT", "RIGHT", "FRONT_LEFT",
                                       "FRONT_RIGHT", "BACK_LEFT", "FRONT_AND_BACK",
                                       "AUX0", "AUX3", "NONE", "TEXTURE_2D"};
    unsigned k;
    getf("AUX_BUFFERS", GL_AUX_BUFFERS, 1);
    getf("DOUBLEBUFFER", GL_DOUBLEBUFFER, 1);
    getf("STEREO", GL_STEREO, 1);
    for (k = 0; k < sizeof draw_enums / sizeof draw_enums[0]; k++) {
        GLint d = -1, r = -1;
        glDrawBuffer(GL_FRONT);
        glReadBuffer(GL_FRONT);
        glGetError();
        glDrawBuffer(draw_enums[k]);
        lg(
                            "DrawBuffer %s err=0x%04x", draw_names[k], glGetError());
        glReadBuffer(draw_enums[k]);
        lg(" ReadBuffer err=0x%04x",
                            glGetError());
        glGetIntegerv(GL_DRAW_BUFFER, &d);
        glGetIntegerv(GL_READ_BUFFER, &r);
        lg(
                            " -> DRAW_BUFFER 0x%04x READ_BUFFER 0x%04x\n", d, r);
    }
    /* drawing and clearing with GL_NONE writes nothing; reading with NONE
     * is an error */
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawBuffer(GL_NONE);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 0.0f);
    glRecti(30, 20, 60, 40);
    ERR("draw with NONE");
    /* a single-buffered OSMesa buffer accepts GL_BACK; what is drawn there? */
    glDrawBuffer(GL_BACK);
    glColor3f(0.0f, 1.0f, 1.0f);
    glRecti(4, 30, 14, 44);
    glDrawBuffer(GL_FRONT_AND_BACK);
    glColor3f(1.0f, 0.0f, 1.0f);
    glRecti(16, 30, 26, 44);
    glDrawBuffer(GL_BACK_LEFT);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 8, 8);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    ERR("draw with BACK");
    glReadBuffer(GL_NONE);
    memset(img, 0xee, 16);
    glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, img);
    lg("ReadPixels with read buffer NONE err=0x%04x untouched=%d\n", glGetError(),
          img[0] == 0xee && img[15] == 0xee);
    glReadBuffer(GL_FRONT);
    /* push/pop: draw buffer in COLOR_BUFFER_BIT, read buffer in PIXEL_MODE_BIT */
    glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
    glDrawBuffer(GL_FRONT_AND_BACK);
    glReadBuffer(GL_LEFT);
    glPopAttrib();
    {
        GLint d = -1, r = -1;
        glGetIntegerv(GL_DRAW_BUFFER, &d);
        glGetIntegerv(GL_READ_BUFFER, &r);
        lg("popped DRAW_BUFFER 0x%04x READ_BUFFER 0x%04x\n", d, r);
    }
    glDrawBuffer(GL_FRONT);
    /* a display list compiles glDrawBuffer */
    {
        GLuint list = glGenLists(1);
        GLint d = -1;
        glNewList(list, GL_COMPILE);
        glDrawBuffer(GL_NONE);
        glEndList();
        glGetIntegerv(GL_DRAW_BUFFER, &d);
        lg("after compile DRAW_BUFFER 0x%04x\n", d);
        glCallList(list);
        glGetIntegerv(GL_DRAW_BUFFER, &d);
        lg("after call DRAW_BUFFER 0x%04x\n", d);
        glRecti(0, 0, 10, 10);
        glDrawBuffer(GL_FRONT);
        glDeleteLists(list, 1);
    }
    flush_log("buffers");
}

static void ext_pointers(void)
{
    static const GLfloat v[8] = {34, 4, 62, 4, 62, 30, 34, 30};
    static const GLubyte col[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                    0, 0, 255, 255, 255, 255, 255, 255};
    static const GLfloat n[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    static const GLfloat tc[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const GLboolean ef[4] = {1, 1, 1, 1};
    static const GLfloat idx[4] = {1, 2, 3, 4};
    void *p = NULL;
    glVertexPointerEXT(2, GL_FLOAT, 0, 4, v);
    ERR("VertexPointerEXT");
    /* (a negative stride is left out: Mesa 22.3 reports GL_INVALID_VALUE but
     * keeps the pointer and stride, and the next draw crashes) */
    glVertexPointerEXT(5, GL_FLOAT, 0, 4, v);
    ERR("VertexPointerEXT size 5");
    glColorPointerEXT(4, GL_UNSIGNED_BYTE, 0, 1, col);
    ERR("ColorPointerEXT count 1");
    glColorPointerEXT(4, GL_UNSIGNED_BYTE, 0, -3, col);
    ERR("ColorPointerEXT count -3");
    glNormalPointerEXT(GL_FLOAT, 0, 4, n);
    ERR("NormalPointerEXT");
    glNormalPointerEXT(GL_UNSIGNED_BYTE, 0, 4, n);
    ERR("NormalPointerEXT ubyte");
    glTexCoordPointerEXT(2, GL_FLOAT, 0, 4, tc);
    ERR("TexCoordPointerEXT");
    glEdgeFlagPointerEXT(0, 4, ef);
    ERR("EdgeFlagPointerEXT");
    glEdgeFlagPointerEXT(-2, 4, ef);
    ERR("EdgeFlagPointerEXT stride -2");
    glIndexPointerEXT(GL_FLOAT, 0, 4, idx);
    ERR("IndexPointerEXT");
    glIndexPointerEXT(GL_UNSIGNED_INT, 0, 4, idx);
    ERR("IndexPointerEXT uint");
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    lg("VERTEX_ARRAY_POINTER matches=%d\n", p == (void *)v);
    glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &p);
    lg("EDGE_FLAG_ARRAY_POINTER matches=%d\n", p == (void *)ef);
    getf("COLOR_ARRAY_SIZE", GL_COLOR_ARRAY_SIZE, 1);
    getf("NORMAL_ARRAY_TYPE", GL_NORMAL_ARRAY_TYPE, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glShadeModel(GL_SMOOTH);
    glDrawArrays(GL_QUADS, 0, 4);
    ERR("DrawArrays EXT pointers");
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    flush_log("ext_pointers");
}

static void eval_grid(void)
{
    getf("MAP1_GRID_DOMAIN initial", GL_MAP1_GRID_DOMAIN, 2);
    getf("MAP1_GRID_SEGMENTS initial", GL_MAP1_GRID_SEGMENTS, 1);
    getf("MAP2_GRID_DOMAIN initial", GL_MAP2_GRID_DOMAIN, 4);
    getf("MAP2_GRID_SEGMENTS initial", GL_MAP2_GRID_SEGMENTS, 2);
    getf("MAX_EVAL_ORDER", GL_MAX_EVAL_ORDER, 1);
    glMapGrid1f(7, 0.25f, 1.5f);
    glMapGrid2d(3, -1.0, 2.0, 5, 0.5, 0.75);
    getf("MAP1_GRID_DOMAIN set", GL_MAP1_GRID_DOMAIN, 2);
    getf("MAP1_GRID_SEGMENTS set", GL_MAP1_GRID_SEGMENTS, 1);
    getf("MAP2_GRID_DOMAIN set", GL_MAP2_GRID_DOMAIN, 4);
    getf("MAP2_GRID_SEGMENTS set", GL_MAP2_GRID_SEGMENTS, 2);
    glPushAttrib(GL_EVAL_BIT);
    glMapGrid1f(2, 0.0f, 1.0f);
    glPopAttrib();
    getf("MAP1_GRID_DOMAIN popped", GL_MAP1_GRID_DOMAIN, 2);
    getf("MAP1_GRID_SEGMENTS popped", GL_MAP1_GRID_SEGMENTS, 1);
    flush_log("eval_grid");
}

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    unsigned char *buf;
    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    buffers(buf);
    index_state();
    imaging();
    compressed();
    multisample();
    ext_pointers();
    eval_grid();
    lg("final error 0x%04x\n", glGetError());
    flush_log("final");

    glFinish();
    sgl_image(out, "frame", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
