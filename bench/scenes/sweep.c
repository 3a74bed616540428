/*
 * sweep.c - one random but valid GL 1.x state, drawn over a fixed set of patches (the seeded state sweep).
 *
 * Run by `bench --sweep N` (bench/README.md) and by the sweep test in
 * tests/osmesa_compare.rs, not by the main benchmark.  The environment
 * variables SWEEP_SEED (default 1) and SWEEP_STATE (default 0) seed a
 * xorshift generator written here; scene_setup draws from it, once, every
 * piece of state: shade model, depth test/func/mask, culling and front face,
 * polygon modes and offset, line width and stipple, point size, polygon
 * stipple, blending (functions, separate functions, equation, constant
 * colour), alpha test, stencil (func, ref, masks, ops), logic op, colour
 * mask, scissor, fog (mode, density, range, coordinate source), lighting (1-3
 * lights: directional, point with attenuation, spot; two-sided, local viewer,
 * separate specular, colour material), the colour sum, 0-2 texture units
 * (internal format of ten, size incl. NPOT, min/mag filter, wrap S/T, border
 * colour, environment incl. GL_COMBINE with its function, sources, operands
 * and scales, texgen, texture matrix) and the primitive type.  It prints the
 * state in words as one line "state ..." on stdout and exits with status 2
 * if the setup raised a GL error.  Every frame clears and draws the same
 * geometry (from a fixed seed, the same for every state): 16 perspective
 * patches of 10x10 cells with colours, secondary colours, normals, fog
 * coordinates and two texture coordinate sets, with the chosen primitive.
 */
#define GL_GLEXT_PROTOTYPES
#define BENCH_STENCIL_BITS 8
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"
#include <math.h>
#include <stdarg.h>

#define PATCHES 16
#define CELLS 10
#define NV ((CELLS + 1) * (CELLS + 1))

/* ---- the generator ---------------------------------------------------------- */

static unsigned int rng;

static unsigned int next_u32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* An integer in [0, n). */
static int pick(int n)
{
    return (int)(next_u32() % (unsigned int)n);
}

/* A float in [lo, hi). */
static float range(float lo, float hi)
{
    return lo + (hi - lo) * (float)(next_u32() >> 8) / 16777216.0f;
}

/* True with probability pct / 100. */
static int chance(int pct)
{
    return pick(100) < pct;
}

/* ---- the description -------------------------------------------------------- */

static char desc[4096];

static void say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

static void say(const char *fmt, ...)
{
    size_t n = strlen(desc);
    va_list ap;
    if (n + 2 >= sizeof desc)
        return;
    if (n > 0)
        desc[n++] = ' ';
    va_start(ap, fmt);
    vsnprintf(desc + n, sizeof desc - n, fmt, ap);
    va_end(ap);
}

/* GL enum names used in the description. */
struct name {
    GLenum e;
    const char *s;
};
#define N(x) {x, #x}
static const struct name names[] = {
    N(GL_NEVER), N(GL_LESS), N(GL_EQUAL), N(GL_LEQUAL), N(GL_GREATER), N(GL_NOTEQUAL),
    N(GL_GEQUAL), N(GL_ALWAYS), N(GL_KEEP), N(GL_ZERO), N(GL_REPLACE), N(GL_INCR),
    N(GL_DECR), N(GL_INVERT), N(GL_INCR_WRAP), N(GL_DECR_WRAP), N(GL_ONE),
    N(GL_SRC_COLOR), N(GL_ONE_MINUS_SRC_COLOR), N(GL_DST_COLOR), N(GL_ONE_MINUS_DST_COLOR),
    N(GL_SRC_ALPHA), N(GL_ONE_MINUS_SRC_ALPHA), N(GL_DST_ALPHA), N(GL_ONE_MINUS_DST_ALPHA),
    N(GL_CONSTANT_COLOR), N(GL_ONE_MINUS_CONSTANT_COLOR), N(GL_CONSTANT_ALPHA),
    N(GL_ONE_MINUS_CONSTANT_ALPHA), N(GL_SRC_ALPHA_SATURATE), N(GL_FUNC_ADD),
    N(GL_FUNC_SUBTRACT), N(GL_FUNC_REVERSE_SUBTRACT), N(GL_MIN), N(GL_MAX), N(GL_CLEAR),
    N(GL_AND), N(GL_AND_REVERSE), N(GL_COPY), N(GL_AND_INVERTED), N(GL_NOOP), N(GL_XOR),
    N(GL_OR), N(GL_NOR), N(GL_EQUIV), N(GL_OR_REVERSE), N(GL_COPY_INVERTED),
    N(GL_OR_INVERTED), N(GL_NAND), N(GL_SET), N(GL_LINEAR), N(GL_EXP), N(GL_EXP2),
    N(GL_NEAREST), N(GL_NEAREST_MIPMAP_NEAREST), N(GL_LINEAR_MIPMAP_NEAREST),
    N(GL_NEAREST_MIPMAP_LINEAR), N(GL_LINEAR_MIPMAP_LINEAR), N(GL_REPEAT), N(GL_CLAMP),
    N(GL_CLAMP_TO_EDGE), N(GL_CLAMP_TO_BORDER), N(GL_MIRRORED_REPEAT), N(GL_MODULATE),
    N(GL_DECAL), N(GL_BLEND), N(GL_ADD), N(GL_COMBINE), N(GL_ADD_SIGNED), N(GL_INTERPOLATE),
    N(GL_SUBTRACT), N(GL_DOT3_RGB), N(GL_DOT3_RGBA), N(GL_TEXTURE), N(GL_CONSTANT),
    N(GL_PRIMARY_COLOR), N(GL_PREVIOUS), N(GL_LUMINANCE8), N(GL_LUMINANCE8_ALPHA8),
    N(GL_INTENSITY8), N(GL_ALPHA8), N(GL_RGB8), N(GL_RGBA8), N(GL_R3_G3_B2), N(GL_RGB5),
    N(GL_RGBA4), N(GL_RGB5_A1), N(GL_OBJECT_LINEAR), N(GL_EYE_LINEAR), N(GL_SPHERE_MAP),
    N(GL_TRIANGLES), N(GL_TRIANGLE_STRIP), N(GL_TRIANGLE_FAN), N(GL_QUADS),
    N(GL_QUAD_STRIP), N(GL_POLYGON), N(GL_LINES), N(GL_LINE_STRIP), N(GL_LINE_LOOP),
    N(GL_POINTS), N(GL_FILL), N(GL_LINE), N(GL_POINT), N(GL_FRONT), N(GL_BACK), N(GL_FRONT_AND_BACK),
    N(GL_CW), N(GL_CCW), N(GL_AMBIENT_AND_DIFFUSE), N(GL_DIFFUSE), N(GL_EMISSION),
    N(GL_FRAGMENT_DEPTH), N(GL_FOG_COORD), N(GL_FLAT), N(GL_SMOOTH),
};
#undef N

/* The name of `e`; primitive types are looked up after N(GL_TRIANGLES) so that
 * GL_POINTS and GL_LINES are not GL_ZERO and GL_ONE. */
static const char *nm_from(GLenum e, const char *first)
{
    size_t i;
    int on = first == NULL;
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        on = on || strcmp(names[i].s, first) == 0;
        if (on && names[i].e == e)
            return names[i].s + 3;
    }
    return "?";
}

static const char *nm(GLenum e)
{
    return nm_from(e, NULL);
}

/* One of the n enums in `list`. */
static GLenum one_of(const GLenum *list, int n)
{
    return list[pick(n)];
}
#define ONE_OF(list) one_of(list, (int)(sizeof list / sizeof list[0]))

/* ---- pieces of state -------------------------------------------------------- */

/* Comparison functions (GL_NEVER, which draws nothing, is left out). */
static const GLenum funcs[] = {GL_LESS,     GL_EQUAL,  GL_LEQUAL, GL_GREATER,
                               GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

static GLenum prim;

static void raster_state(void)
{
    static const GLenum modes[] = {GL_FILL, GL_FILL, GL_FILL, GL_LINE, GL_POINT};
    GLenum sm = chance(25) ? GL_FLAT : GL_SMOOTH;
    glShadeModel(sm);
    say("shade=%s", nm(sm));
    if (chance(70)) {
        GLenum f = chance(60) ? GL_LESS : ONE_OF(funcs);
        GLboolean mask = (GLboolean)chance(85);
        /* EQUAL would pass nothing against a cleared buffer; GREATER and GEQUAL
         * pass against a buffer cleared to 0. */
        if (f == GL_EQUAL)
            f = GL_LEQUAL;
        if (f == GL_GREATER || f == GL_GEQUAL)
            glClearDepth(0.0);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(f);
        glDepthMask(mask);
        say("depth=%s%s", nm(f), mask ? "" : ",nowrite");
    }
    if (chance(30)) {
        static const GLenum faces[] = {GL_FRONT, GL_BACK};
        GLenum c = ONE_OF(faces), ff = chance(50) ? GL_CW : GL_CCW;
        glEnable(GL_CULL_FACE);
        glCullFace(c);
        glFrontFace(ff);
        say("cull=%s front=%s", nm(c), nm(ff));
    }
    if (chance(35)) {
        GLenum pf = ONE_OF(modes), pb = ONE_OF(modes);
        glPolygonMode(GL_FRONT, pf);
        glPolygonMode(GL_BACK, pb);
        say("polymode=%s/%s", nm(pf), nm(pb));
    }
    if (chance(20)) {
        float f = range(-2.0f, 2.0f), u = (float)(pick(9) - 4);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glEnable(GL_POLYGON_OFFSET_LINE);
        glPolygonOffset(f, u);
        say("offset=%.2f,%.0f", (double)f, (double)u);
    }
    if (chance(40)) {
        float w = (float)(1 + pick(3));
        glLineWidth(w);
        say("linewidth=%.0f", (double)w);
    }
    if (chance(15)) {
        int factor = 1 + pick(3);
        GLushort pat = (GLushort)(next_u32() | 0x0101u);
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(factor, pat);
        say("linestipple=%d,0x%04x", factor, pat);
    }
    if (chance(40)) {
        float s = (float)(1 + pick(5));
        glPointSize(s);
        say("pointsize=%.0f", (double)s);
    }
    if (chance(10)) {
        GLubyte st[128];
        int i;
        for (i = 0; i < 128; i++)
            st[i] = (GLubyte)next_u32();
        glEnable(GL_POLYGON_STIPPLE);
        glPolygonStipple(st);
        say("polystipple");
    }
}

static void fragment_state(int w, int h)
{
    static const GLenum factors[] = {
        GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
        GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
        GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
        GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
    static const GLenum eqs[] = {GL_FUNC_ADD, GL_FUNC_ADD, GL_FUNC_SUBTRACT,
                                 GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    static const GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                                 GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
    static const GLenum logic[] = {GL_CLEAR, GL_AND, GL_AND_REVERSE, GL_COPY,
                                   GL_AND_INVERTED, GL_XOR, GL_OR,
                                   GL_NOR, GL_EQUIV, GL_INVERT, GL_OR_REVERSE,
                                   GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND, GL_SET};
    if (chance(45)) {
        /* SRC_ALPHA_SATURATE is a source factor only in GL 1.x. */
        GLenum s = ONE_OF(factors), d = one_of(factors, 14), e = ONE_OF(eqs);
        float c[4] = {range(0, 1), range(0, 1), range(0, 1), range(0, 1)};
        glEnable(GL_BLEND);
        if (chance(25)) {
            GLenum sa = ONE_OF(factors), da = one_of(factors, 14);
            glBlendFuncSeparate(s, d, sa, da);
            say("blend=%s,%s/%s,%s", nm(s), nm(d), nm(sa), nm(da));
        } else {
            glBlendFunc(s, d);
            say("blend=%s,%s", nm(s), nm(d));
        }
        glBlendEquation(e);
        glBlendColor(c[0], c[1], c[2], c[3]);
        say("eq=%s", nm(e));
    }
    if (chance(25)) {
        GLenum f = ONE_OF(funcs);
        float r = range(0.0f, 1.0f);
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(f, r);
        say("alpha=%s,%.3f", nm(f), (double)r);
    }
    if (chance(25)) {
        GLenum f = ONE_OF(funcs), sf = ONE_OF(ops), df = ONE_OF(ops), dp = ONE_OF(ops);
        int ref = pick(256), mask = chance(50) ? 0xFF : pick(256);
        int wmask = chance(60) ? 0xFF : pick(256);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(f, ref, (GLuint)mask);
        glStencilOp(sf, df, dp);
        glStencilMask((GLuint)wmask);
        glClearStencil(pick(256));
        say("stencil=%s,%d,0x%02x ops=%s,%s,%s wmask=0x%02x", nm(f), ref, mask, nm(sf),
            nm(df), nm(dp), wmask);
    }
    if (chance(10)) {
        GLenum op = ONE_OF(logic);
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(op);
        say("logicop=%s", nm(op));
    }
    if (chance(12)) {
        GLboolean m[4];
        int i;
        for (i = 0; i < 4; i++)
            m[i] = (GLboolean)chance(70);
        if (!m[0] && !m[1] && !m[2])
            m[pick(3)] = GL_TRUE;
        glColorMask(m[0], m[1], m[2], m[3]);
        say("colormask=%d%d%d%d", m[0], m[1], m[2], m[3]);
    }
    if (chance(20)) {
        int x = pick(w / 2), y = pick(h / 2);
        int sw = w / 4 + pick(w / 2), sh = h / 4 + pick(h / 2);
        glEnable(GL_SCISSOR_TEST);
        glScissor(x, y, sw, sh);
        say("scissor=%d,%d,%d,%d", x, y, sw, sh);
    }
    if (chance(25)) {
        static const GLenum modes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
        GLenum m = ONE_OF(modes);
        float c[4] = {range(0, 1), range(0, 1), range(0, 1), range(0, 1)};
        float d = range(0.05f, 0.6f), s = range(0.0f, 3.0f), e = s + range(0.5f, 6.0f);
        GLenum src = chance(30) ? GL_FOG_COORD : GL_FRAGMENT_DEPTH;
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, (GLint)m);
        glFogfv(GL_FOG_COLOR, c);
        glFogf(GL_FOG_DENSITY, d);
        glFogf(GL_FOG_START, s);
        glFogf(GL_FOG_END, e);
        glFogi(GL_FOG_COORD_SRC, (GLint)src);
        say("fog=%s,%s", nm(m), nm(src));
    }
}

static void lighting_state(void)
{
    static const GLenum cm[] = {GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_EMISSION};
    int n, i;
    if (!chance(40))
        return;
    n = 1 + pick(3);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    say("lights=%d:", n);
    for (i = 0; i < n; i++) {
        GLenum l = GL_LIGHT0 + (GLenum)i;
        int kind = pick(3);
        GLfloat pos[4] = {range(-3, 3), range(-3, 3), range(-1, 4), kind == 0 ? 0.0f : 1.0f};
        GLfloat col[4] = {range(0.3f, 1), range(0.3f, 1), range(0.3f, 1), 1.0f};
        glEnable(l);
        glLightfv(l, GL_POSITION, pos);
        glLightfv(l, GL_DIFFUSE, col);
        glLightfv(l, GL_SPECULAR, col);
        if (kind >= 1) {
            glLightf(l, GL_CONSTANT_ATTENUATION, range(0.5f, 1.0f));
            glLightf(l, GL_LINEAR_ATTENUATION, range(0.0f, 0.3f));
            glLightf(l, GL_QUADRATIC_ATTENUATION, range(0.0f, 0.1f));
        }
        if (kind == 2) {
            GLfloat dir[3] = {-pos[0], -pos[1], -pos[2] - 3.0f};
            glLightfv(l, GL_SPOT_DIRECTION, dir);
            glLightf(l, GL_SPOT_CUTOFF, range(15.0f, 70.0f));
            glLightf(l, GL_SPOT_EXPONENT, range(0.0f, 30.0f));
        }
        say("%s", kind == 0 ? "dir" : kind == 1 ? "point" : "spot");
    }
    if (chance(40)) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        say("twoside");
    }
    if (chance(30)) {
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
        say("localviewer");
    }
    if (chance(40)) {
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        say("separatespecular");
    }
    {
        GLfloat spec[4] = {range(0, 1), range(0, 1), range(0, 1), 1.0f};
        float shin = range(1.0f, 100.0f);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shin);
        say("shininess=%.1f", (double)shin);
    }
    if (chance(60)) {
        GLenum m = ONE_OF(cm);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, m);
        say("colormaterial=%s", nm(m));
    }
}

/* ---- textures --------------------------------------------------------------- */

/* Internal formats, with the client format that matches them. */
static const struct {
    GLenum internal, format;
    int comps;
} tex_formats[] = {
    {GL_LUMINANCE8, GL_LUMINANCE, 1},
    {GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, 2},
    {GL_INTENSITY8, GL_LUMINANCE, 1},
    {GL_ALPHA8, GL_ALPHA, 1},
    {GL_RGB8, GL_RGB, 3},
    {GL_RGBA8, GL_RGBA, 4},
    {GL_R3_G3_B2, GL_RGB, 3},
    {GL_RGB5, GL_RGB, 3},
    {GL_RGBA4, GL_RGBA, 4},
    {GL_RGB5_A1, GL_RGBA, 4},
};

/* Uploads every mip level of a w x h texture: each level is the same pattern
 * drawn at its own size, tinted by level (a chain made by hand, as the same
 * bytes on both sides). */
static void upload(int fmt, int w, int h, int seed)
{
    static unsigned char data[64 * 64 * 4];
    int level = 0, comps = tex_formats[fmt].comps;
    for (;;) {
        int x, y, c;
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                for (c = 0; c < comps; c++) {
                    float u = ((float)x + 0.5f) / (float)w, v = ((float)y + 0.5f) / (float)h;
                    int check = ((int)(u * 8.0f) ^ (int)(v * 8.0f)) & 1;
                    float val = check ? 0.85f : 0.2f;
                    val += 0.15f * sinf(6.0f * u + (float)(c + seed)) - 0.1f * (float)level / 6.0f;
                    val = 0.5f * val + 0.5f * ((c & 1) ? u : v);
                    val = val < 0.0f ? 0.0f : val > 1.0f ? 1.0f : val;
                    data[(y * w + x) * comps + c] = (unsigned char)(val * 255.0f);
                }
        glTexImage2D(GL_TEXTURE_2D, level, (GLint)tex_formats[fmt].internal, w, h, 0,
                     tex_formats[fmt].format, GL_UNSIGNED_BYTE, data);
        if (w == 1 && h == 1)
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        level++;
    }
}

static void texgen_coord(GLenum coord, GLenum mode)
{
    GLfloat plane[4] = {range(-1, 1), range(-1, 1), range(-1, 1), range(-1, 1)};
    glTexGeni(coord, GL_TEXTURE_GEN_MODE, (GLint)mode);
    if (mode == GL_OBJECT_LINEAR)
        glTexGenfv(coord, GL_OBJECT_PLANE, plane);
    else if (mode == GL_EYE_LINEAR)
        glTexGenfv(coord, GL_EYE_PLANE, plane);
    glEnable(coord == GL_S ? GL_TEXTURE_GEN_S : GL_TEXTURE_GEN_T);
}

static void combine_state(void)
{
    static const GLenum rgb_f[] = {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED,
                                   GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
    static const GLenum srcs[] = {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS};
    static const GLenum ops_rgb[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                     GL_ONE_MINUS_SRC_ALPHA};
    static const GLenum ops_a[] = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
    static const int scales[] = {1, 1, 2, 4};
    GLenum fr = ONE_OF(rgb_f), fa = one_of(rgb_f, 6);
    int i, rs = scales[pick(4)], as = scales[pick(4)];
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)fr);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)fa);
    say("combine=%s/%s", nm(fr), nm(fa));
    for (i = 0; i < 3; i++) {
        GLenum s = ONE_OF(srcs), o = ONE_OF(ops_rgb), sa = ONE_OF(srcs), oa = ONE_OF(ops_a);
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + (GLenum)i, (GLint)s);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + (GLenum)i, (GLint)o);
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + (GLenum)i, (GLint)sa);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + (GLenum)i, (GLint)oa);
        say("arg%d=%s:%s/%s:%s", i, nm(s), nm(o), nm(sa), nm(oa));
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, rs);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, as);
    say("scale=%d/%d", rs, as);
}

static void texture_unit(int unit)
{
    static const GLenum mins[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR};
    static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                   GL_MIRRORED_REPEAT};
    static const GLenum envs[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD,
                                  GL_COMBINE, GL_COMBINE};
    static const int sizes[][2] = {{64, 64}, {32, 32}, {16, 64}, {48, 40}, {37, 21}};
    GLuint tex;
    int fmt = pick((int)(sizeof tex_formats / sizeof tex_formats[0]));
    int sz = pick(5);
    GLenum mn = ONE_OF(mins), mg = chance(50) ? GL_NEAREST : GL_LINEAR;
    GLenum ws = ONE_OF(wraps), wt = ONE_OF(wraps), env = ONE_OF(envs);
    GLfloat border[4] = {range(0, 1), range(0, 1), range(0, 1), range(0, 1)};
    GLfloat envc[4] = {range(0, 1), range(0, 1), range(0, 1), range(0, 1)};
    /* DECAL is undefined for the luminance, intensity and alpha formats. */
    if (env == GL_DECAL && tex_formats[fmt].comps < 3)
        env = GL_MODULATE;
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    upload(fmt, sizes[sz][0], sizes[sz][1], unit);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)mn);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mg);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)ws);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wt);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    glEnable(GL_TEXTURE_2D);
    say("tex%d=%s,%dx%d min=%s mag=%s wrap=%s/%s env=%s", unit, nm(tex_formats[fmt].internal),
        sizes[sz][0], sizes[sz][1], nm(mn), nm(mg), nm(ws), nm(wt), nm(env));
    if (env == GL_COMBINE)
        combine_state();
    if (chance(20)) {
        static const GLenum gens[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP};
        GLenum g = ONE_OF(gens);
        texgen_coord(GL_S, g);
        texgen_coord(GL_T, g);
        say("texgen=%s", nm(g));
    }
    if (chance(25)) {
        float a = range(0.0f, 90.0f), s = range(0.5f, 3.0f);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glRotatef(a, 0.0f, 0.0f, 1.0f);
        glScalef(s, s, 1.0f);
        glMatrixMode(GL_MODELVIEW);
        say("texmatrix=rot%.0f,scale%.2f", (double)a, (double)s);
    }
}

/* ---- geometry --------------------------------------------------------------- */

struct vertex {
    float pos[3], nrm[3], col[4], sec[3], fog, tc0[2], tc1[2];
};

static struct vertex verts[PATCHES][NV];

/* The fixed geometry: PATCHES wavy grids at random places and tilts, from a fixed seed. */
static void make_geometry(void)
{
    int p, i, j;
    rng = 0x9E3779B9u;
    for (p = 0; p < PATCHES; p++) {
        float cx = range(-1.4f, 1.4f), cy = range(-1.4f, 1.4f), cz = range(-5.5f, -3.0f);
        float sx = range(1.5f, 3.2f), sy = range(1.5f, 3.2f);
        float tilt = range(-0.8f, 0.8f), twist = range(-0.6f, 0.6f), amp = range(0.0f, 0.3f);
        float c0[4] = {range(0, 1), range(0, 1), range(0, 1), range(0.2f, 1)};
        float c1[4] = {range(0, 1), range(0, 1), range(0, 1), range(0.2f, 1)};
        float ts = range(0.5f, 2.5f), to = range(-0.5f, 0.5f);
        for (j = 0; j <= CELLS; j++)
            for (i = 0; i <= CELLS; i++) {
                struct vertex *v = &verts[p][j * (CELLS + 1) + i];
                float u = (float)i / CELLS, t = (float)j / CELLS;
                float x = (u - 0.5f) * sx, y = (t - 0.5f) * sy;
                float z = amp * sinf(7.0f * u) * cosf(5.0f * t);
                float k, nx, ny, nz, l;
                v->pos[0] = cx + x;
                v->pos[1] = cy + y * cosf(tilt);
                v->pos[2] = cz + y * sinf(tilt) + x * twist + z;
                nx = -amp * 7.0f * cosf(7.0f * u) * cosf(5.0f * t) / sx - twist;
                ny = amp * 5.0f * sinf(7.0f * u) * sinf(5.0f * t) / sy - sinf(tilt);
                nz = 1.0f;
                l = sqrtf(nx * nx + ny * ny + nz * nz);
                v->nrm[0] = nx / l;
                v->nrm[1] = ny / l;
                v->nrm[2] = nz / l;
                for (k = 0; k < 4; k++) {
                    int c = (int)k;
                    v->col[c] = c0[c] + (c1[c] - c0[c]) * (c & 1 ? u : t);
                }
                v->sec[0] = 0.4f * t;
                v->sec[1] = 0.3f * u;
                v->sec[2] = 0.2f;
                v->fog = 6.0f * u * t;
                v->tc0[0] = to + ts * (u - 0.25f);
                v->tc0[1] = to + ts * (t - 0.25f);
                v->tc1[0] = 1.5f * t - 0.2f;
                v->tc1[1] = 1.2f * u + 0.1f;
            }
    }
}

static void emit(const struct vertex *v)
{
    glColor4fv(v->col);
    glSecondaryColor3fv(v->sec);
    glNormal3fv(v->nrm);
    glFogCoordf(v->fog);
    glMultiTexCoord2fv(GL_TEXTURE0, v->tc0);
    glMultiTexCoord2fv(GL_TEXTURE1, v->tc1);
    glVertex3fv(v->pos);
}

#define V(i, j) (&vs[(j) * (CELLS + 1) + (i)])

static void draw_patch(const struct vertex *vs)
{
    int i, j;
    switch (prim) {
    case GL_TRIANGLES:
    case GL_QUADS:
    case GL_LINES:
        glBegin(prim);
        for (j = 0; j < CELLS; j++)
            for (i = 0; i < CELLS; i++) {
                if (prim == GL_TRIANGLES) {
                    emit(V(i, j)), emit(V(i + 1, j)), emit(V(i + 1, j + 1));
                    emit(V(i, j)), emit(V(i + 1, j + 1)), emit(V(i, j + 1));
                } else if (prim == GL_QUADS) {
                    emit(V(i, j)), emit(V(i + 1, j)), emit(V(i + 1, j + 1)), emit(V(i, j + 1));
                } else {
                    emit(V(i, j)), emit(V(i + 1, j)), emit(V(i, j)), emit(V(i, j + 1));
                }
            }
        glEnd();
        break;
    case GL_TRIANGLE_STRIP:
    case GL_QUAD_STRIP:
        for (j = 0; j < CELLS; j++) {
            glBegin(prim);
            for (i = 0; i <= CELLS; i++)
                emit(V(i, j + 1)), emit(V(i, j));
            glEnd();
        }
        break;
    case GL_TRIANGLE_FAN:
    case GL_POLYGON:
    case GL_LINE_LOOP:
        /* one fan / polygon / loop per 2x2 cells, around its centre vertex */
        for (j = 1; j < CELLS; j += 2)
            for (i = 1; i < CELLS; i += 2) {
                glBegin(prim);
                if (prim == GL_TRIANGLE_FAN)
                    emit(V(i, j));
                emit(V(i - 1, j - 1)), emit(V(i, j - 1)), emit(V(i + 1, j - 1));
                emit(V(i + 1, j)), emit(V(i + 1, j + 1)), emit(V(i, j + 1));
                emit(V(i - 1, j + 1)), emit(V(i - 1, j));
                if (prim == GL_TRIANGLE_FAN)
                    emit(V(i - 1, j - 1));
                glEnd();
            }
        break;
    case GL_LINE_STRIP:
        for (j = 0; j <= CELLS; j++) {
            glBegin(prim);
            for (i = 0; i <= CELLS; i++)
                emit(V(i, j));
            glEnd();
        }
        break;
    default:
        glBegin(GL_POINTS);
        for (i = 0; i < NV; i++)
            emit(&vs[i]);
        glEnd();
        break;
    }
}

/* ---- the scene -------------------------------------------------------------- */

static void scene_setup(int w, int h)
{
    static const GLenum prims[] = {GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP,
                                   GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON,
                                   GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_POINTS};
    const char *seed_s = getenv("SWEEP_SEED"), *state_s = getenv("SWEEP_STATE");
    unsigned int seed = seed_s && *seed_s ? (unsigned int)strtoul(seed_s, NULL, 10) : 1u;
    unsigned int state = state_s && *state_s ? (unsigned int)strtoul(state_s, NULL, 10) : 0u;
    float cc[4];
    int units;
    GLenum err;

    make_geometry();
    /* Mix seed and state into a non-zero xorshift state, then warm it up. */
    rng = (seed * 0x9E3779B1u) ^ (state * 0x85EBCA77u) ^ 0x27D4EB2Fu;
    if (rng == 0)
        rng = 1;
    for (units = 0; units < 8; units++)
        next_u32();

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    prim = ONE_OF(prims);
    say("prim=%s", nm_from(prim, "GL_TRIANGLES"));
    cc[0] = range(0, 1), cc[1] = range(0, 1), cc[2] = range(0, 1), cc[3] = range(0, 1);
    glClearColor(cc[0], cc[1], cc[2], cc[3]);
    raster_state();
    fragment_state(w, h);
    lighting_state();
    if (chance(20)) {
        glEnable(GL_COLOR_SUM);
        say("colorsum");
    }
    units = pick(10) < 3 ? 0 : pick(10) < 6 ? 1 : 2;
    if (units >= 1)
        texture_unit(0);
    if (units >= 2)
        texture_unit(1);
    glActiveTexture(GL_TEXTURE0);
    printf("state %s\n", desc);
    err = glGetError();
    if (err != GL_NO_ERROR) {
        fprintf(stderr, "GL error 0x%04x in the state setup: %s\n", err, desc);
        exit(2);
    }
}

static void scene_frame(int w, int h)
{
    int p;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    for (p = 0; p < PATCHES; p++)
        draw_patch(verts[p]);
}
