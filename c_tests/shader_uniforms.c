/* shader_uniforms: a linked program's interface against Mesa's, without
 * drawing: the active attributes and uniforms (names, types, sizes; listed in
 * name order, since GL leaves the order to the implementation), attribute
 * locations from glBindAttribLocation, glGetUniformLocation of plain, array
 * element and struct member names (printed as found / not found and as offsets
 * from the array's first element: the numbers themselves are the
 * implementation's), every glUniform{1,2,3,4}{f,i}[v] and
 * glUniformMatrix{2,3,4,2x3,...}fv form read back with glGetUniform{f,i}v (as
 * exact hex floats; transposed matrices; bool conversions; counts past an
 * array's end), initializers, and the errors: no current program, type and
 * size mismatches, count > 1 for a non-array, negative counts, location -1,
 * bad locations, sampler ranges. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "errcheck.h"

static const char *VS =
    "#version 120\n"
    "attribute vec4 pos;\n"
    "attribute vec3 nrm;\n"
    "attribute mat3 basis;\n"
    "attribute float unused_attr;\n"
    "attribute vec2 bound;\n"
    "uniform mat4 mvp;\n"
    "uniform vec3 light[3];\n"
    "uniform float scale = 2.5;\n"
    "uniform mat2x3 skew;\n"
    "uniform float only_vs_unused;\n"
    "struct Mat { vec4 diffuse; float shine; int mode[2]; };\n"
    "uniform Mat mat;\n"
    "varying vec4 col;\n"
    "void main() {\n"
    "  vec3 n = basis * nrm + light[0] + light[2] + skew * vec2(bound.x, 1.0);\n"
    "  col = mat.diffuse * mat.shine * float(mat.mode[1]) + vec4(n, 1.0);\n"
    "  gl_Position = mvp * pos * scale;\n"
    "}\n";

static const char *FS =
    "#version 120\n"
    "uniform sampler2D tex;\n"
    "uniform vec4 tint;\n"
    "uniform ivec2 iv;\n"
    "uniform bool flag;\n"
    "uniform bvec3 flags;\n"
    "uniform float arr[4];\n"
    "uniform mat3 m3;\n"
    "uniform mat4x2 m42;\n"
    "uniform float scale = 2.5;\n"
    "varying vec4 col;\n"
    "void main() {\n"
    "  vec4 c = texture2D(tex, col.xy) * tint * float(iv.x + iv.y);\n"
    "  if (flag && flags.y) c += vec4(arr[1] + arr[2]);\n"
    "  c.xyz += m3 * c.xyz;\n"
    "  c.xy += m42 * c;\n"
    "  gl_FragColor = c * scale;\n"
    "}\n";

static GLuint compile(GLenum type, const char *src)
{
    GLuint s = glCreateShader(type);
    GLint ok = 0;
    char log[1024] = "";
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    sgl_text(out, "compile", "status %d log [%s]\n", ok, log);
    return s;
}

/* the active uniforms or attributes of p, as lines sorted by name */
static void actives(GLuint p, int uniforms)
{
    GLint n = 0, maxlen = 0, i;
    static char lines[64][160];
    glGetProgramiv(p, uniforms ? GL_ACTIVE_UNIFORMS : GL_ACTIVE_ATTRIBUTES, &n);
    glGetProgramiv(p, uniforms ? GL_ACTIVE_UNIFORM_MAX_LENGTH : GL_ACTIVE_ATTRIBUTE_MAX_LENGTH,
                   &maxlen);
    sgl_text(out, "active", "%s: %d, max length %d\n", uniforms ? "uniforms" : "attributes", n,
             maxlen);
    SGL_CHECK(n <= 64);
    for (i = 0; i < n; i++) {
        char name[128];
        GLsizei len = -7;
        GLint size = -7;
        GLenum type = 0;
        memset(name, 0, sizeof name);
        if (uniforms)
            glGetActiveUniform(p, i, sizeof name, &len, &size, &type, name);
        else
            glGetActiveAttrib(p, i, sizeof name, &len, &size, &type, name);
        snprintf(lines[i], sizeof lines[i], "%-20s len %2d size %d type 0x%04x", name, len, size,
                 type);
    }
    qsort(lines, (size_t)n, sizeof lines[0], by_name);
    for (i = 0; i < n; i++)
        sgl_text(out, "active", "%s\n", lines[i]);
}

static void getf(GLuint p, const char *name, int n)
{
    GLint loc = glGetUniformLocation(p, name);
    GLfloat f[16];
    GLint iv[16];
    int k;
    char line[1024];
    int at = 0;
    for (k = 0; k < 16; k++) {
        f[k] = -77.0f;
        iv[k] = -77;
    }
    glGetUniformfv(p, loc, f);
    glGetUniformiv(p, loc, iv);
    at += snprintf(line + at, sizeof line - (size_t)at, "%-12s found %d:", name, loc >= 0);
    for (k = 0; k < n; k++)
        at += snprintf(line + at, sizeof line - (size_t)at, " %a/%d", f[k], iv[k]);
    sgl_text(out, "value", "%s err 0x%04x\n", line, glGetError());
}

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    void *buf;
    GLuint vs, fs, p;
    GLint ok = -7, v, loc, base;
    char log[1024] = "";
    static const char *names[] = {"mvp",      "light",   "light[0]", "light[1]", "light[2]",
                                  "light[3]", "scale",   "skew",     "mat.diffuse", "mat.shine",
                                  "mat.mode", "mat.mode[1]", "mat.mode[2]", "mat",  "tex",
                                  "tint",     "iv",      "flag",     "flags",    "arr",
                                  "arr[2]",   "arr[3]",  "m3",       "m42",      "only_vs_unused",
                                  "nope",     "gl_ModelViewMatrix", "light[",  "light[-1]",
                                  "light[0]x", ""};
    unsigned k;
    GLfloat m[16];
    GLint iv4[8] = {3, -4, 5, 6, 7, 8, 9, 10};
    GLfloat f4[16];

    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx);
    buf = malloc(16 * 16 * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16));
    for (k = 0; k < 16; k++) {
        m[k] = (GLfloat)k + 0.25f;
        f4[k] = 1.0f / (GLfloat)(k + 3);
    }

    vs = compile(GL_VERTEX_SHADER, VS);
    fs = compile(GL_FRAGMENT_SHADER, FS);
    p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    E(glBindAttribLocation(p, 5, "bound"));
    E(glBindAttribLocation(p, 9, "not_in_shader"));
    E(glBindAttribLocation(p, 16, "pos"));
    E(glBindAttribLocation(p, 1, "gl_Vertex"));
    E(glBindAttribLocation(p, 1, NULL));
    E(glGetUniformLocation(p, "mvp"));
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    glGetProgramInfoLog(p, sizeof log, NULL, log);
    sgl_text(out, "link", "status %d log [%s]\n", ok, log);
    actives(p, 0);
    actives(p, 1);
    sgl_text(out, "attrib", "bound at %d, gl_Vertex %d, unused %d, nope %d err 0x%04x\n",
             glGetAttribLocation(p, "bound"), glGetAttribLocation(p, "gl_Vertex"),
             glGetAttribLocation(p, "unused_attr"), glGetAttribLocation(p, "nope"),
             glGetError());
    {
        GLint a = glGetAttribLocation(p, "pos"), b = glGetAttribLocation(p, "nrm"),
              c = glGetAttribLocation(p, "basis");
        sgl_text(out, "attrib", "pos %d nrm %d basis %d: distinct %d, basis run free %d\n",
                 a >= 0, b >= 0, c >= 0, a != b && a != c && b != c,
                 !(a >= c && a < c + 3) && !(b >= c && b < c + 3) && !(5 >= c && 5 < c + 3));
    }

    /* locations */
    base = glGetUniformLocation(p, "light");
    for (k = 0; k < sizeof names / sizeof names[0]; k++) {
        loc = glGetUniformLocation(p, names[k]);
        sgl_text(out, "location", "%-20s found %d", names[k], loc >= 0);
        if (strncmp(names[k], "light", 5) == 0 && loc >= 0)
            sgl_text(out, "location", " offset %d", loc - base);
        sgl_text(out, "location", " err 0x%04x\n", glGetError());
    }
    base = glGetUniformLocation(p, "arr");
    sgl_text(out, "location", "arr[1] offset %d arr[2] offset %d\n",
             glGetUniformLocation(p, "arr[1]") - base, glGetUniformLocation(p, "arr[2]") - base);

    /* no program in use yet */
    E(glUniform1f(glGetUniformLocation(p, "scale"), 1.0f));
    E(glUniform1f(-1, 1.0f));
    E(glUseProgram(p));
    glGetIntegerv(GL_CURRENT_PROGRAM, &v);
    sgl_text(out, "current", "is p %d\n", v == (GLint)p);

    /* initial values */
    getf(p, "scale", 1);
    getf(p, "tint", 4);
    getf(p, "mat.mode[1]", 1);

    /* every form */
    E(glUniform1f(glGetUniformLocation(p, "scale"), 0.75f));
    E(glUniform4f(glGetUniformLocation(p, "tint"), 0.5f, -1.5f, 2.25f, 1e10f));
    E(glUniform4fv(glGetUniformLocation(p, "tint"), 1, f4));
    E(glUniform2i(glGetUniformLocation(p, "iv"), -3, 70000));
    E(glUniform2iv(glGetUniformLocation(p, "iv"), 1, iv4));
    E(glUniform1i(glGetUniformLocation(p, "flag"), 5));
    E(glUniform3f(glGetUniformLocation(p, "flags"), 0.0f, -0.5f, 2.0f));
    E(glUniform3fv(glGetUniformLocation(p, "light"), 3, f4));
    E(glUniform3fv(glGetUniformLocation(p, "light[1]"), 5, m));
    E(glUniform1fv(glGetUniformLocation(p, "arr[1]"), 2, f4 + 5));
    E(glUniform1i(glGetUniformLocation(p, "tex"), 3));
    E(glUniform1iv(glGetUniformLocation(p, "mat.mode"), 2, iv4));
    E(glUniform1f(glGetUniformLocation(p, "mat.shine"), 3.5f));
    E(glUniformMatrix4fv(glGetUniformLocation(p, "mvp"), 1, GL_FALSE, m));
    E(glUniformMatrix3fv(glGetUniformLocation(p, "m3"), 1, GL_TRUE, m));
    E(glUniformMatrix2x3fv(glGetUniformLocation(p, "skew"), 1, GL_FALSE, f4));
    E(glUniformMatrix4x2fv(glGetUniformLocation(p, "m42"), 1, GL_TRUE, m));
    getf(p, "scale", 1);
    getf(p, "tint", 4);
    getf(p, "iv", 2);
    getf(p, "flag", 1);
    getf(p, "flags", 3);
    getf(p, "light[0]", 3);
    getf(p, "light[1]", 3);
    getf(p, "light[2]", 3);
    getf(p, "arr[1]", 1);
    getf(p, "arr[2]", 1);
    getf(p, "tex", 1);
    getf(p, "mat.mode", 1);
    getf(p, "mat.mode[1]", 1);
    getf(p, "mat.shine", 1);
    getf(p, "mvp", 16);
    getf(p, "m3", 9);
    getf(p, "skew", 6);
    getf(p, "m42", 8);

    /* errors */
    loc = glGetUniformLocation(p, "tint");
    E(glUniform3f(loc, 1.0f, 2.0f, 3.0f));
    E(glUniform4i(loc, 1, 2, 3, 4));
    E(glUniform4fv(loc, 2, f4));
    E(glUniform4fv(loc, -1, f4));
    E(glUniformMatrix2fv(loc, 1, GL_FALSE, f4));
    loc = glGetUniformLocation(p, "iv");
    E(glUniform2f(loc, 1.0f, 2.0f));
    loc = glGetUniformLocation(p, "mvp");
    E(glUniform4fv(loc, 4, f4));
    E(glUniformMatrix3fv(loc, 1, GL_FALSE, f4));
    E(glUniformMatrix4x3fv(loc, 1, GL_FALSE, f4));
    loc = glGetUniformLocation(p, "tex");
    E(glUniform1f(loc, 1.0f));
    E(glUniform1i(loc, -1));
    E(glUniform1i(loc, 1000));
    E(glUniform2i(loc, 1, 2));
    loc = glGetUniformLocation(p, "flags");
    E(glUniform3i(loc, 0, 7, 0));
    getf(p, "flags", 3);
    E(glUniform1f(-1, 2.0f));
    E(glUniform4fv(-1, -1, f4));
    E(glUniform1f(-2, 2.0f));
    E(glUniform1f(100000, 2.0f));
    E(glUniform1fv(glGetUniformLocation(p, "arr"), 0, f4));
    {
        GLfloat f = -1.0f;
        E(glGetUniformfv(p, -1, &f));
        E(glGetUniformfv(p, 100000, &f));
        E(glGetUniformfv(12345, 0, &f));
        E(glGetUniformfv(vs, 0, &f));
    }
    {
        char name[8];
        GLsizei len = -7;
        GLint size = -7;
        GLenum type = 0;
        E(glGetActiveUniform(p, 1000, sizeof name, &len, &size, &type, name));
        E(glGetActiveUniform(p, 0, -1, &len, &size, &type, name));
        E(glGetActiveAttrib(p, 1000, sizeof name, &len, &size, &type, name));
        E(glGetActiveUniform(vs, 0, sizeof name, &len, &size, &type, name));
        E(glGetActiveAttrib(12345, 0, sizeof name, &len, &size, &type, name));
        memset(name, 0, sizeof name);
        glGetActiveUniform(p, 0, 3, &len, &size, &type, name);
        sgl_text(out, "short", "len %d name length %d err 0x%04x\n", len, (int)strlen(name),
                 glGetError());
    }
    E(glGetUniformLocation(12345, "mvp"));
    E(glGetUniformLocation(vs, "mvp"));
    E(glGetAttribLocation(12345, "pos"));
    E(glGetAttribLocation(vs, "pos"));
    E(glBindAttribLocation(12345, 1, "pos"));
    E(glBindAttribLocation(vs, 1, "pos"));

    /* an unlinked program's queries */
    {
        GLuint q = glCreateProgram();
        GLfloat f = -1.0f;
        E(glGetUniformLocation(q, "mvp"));
        E(glGetAttribLocation(q, "pos"));
        E(glGetUniformfv(q, 0, &f));
        glDeleteProgram(q);
    }

    /* relinking after a binding moves the attribute; values reset */
    E(glBindAttribLocation(p, 7, "pos"));
    glLinkProgram(p);
    sgl_text(out, "relink", "pos at %d, bound at %d\n", glGetAttribLocation(p, "pos"),
             glGetAttribLocation(p, "bound"));
    getf(p, "scale", 1);
    getf(p, "tint", 4);

    E(glUseProgram(0));
    E(glUniform1f(glGetUniformLocation(p, "scale"), 1.0f));
    E(glUniform1f(-1, 1.0f));

    /* the ARB_shader_objects names */
    {
        GLint t = -7;
        GLuint h;
        GLsizei n = -7;
        char l[64] = "";
        glGetObjectParameterivARB(p, GL_OBJECT_TYPE_ARB, &t);
        sgl_text(out, "arb", "program type 0x%04x err 0x%04x\n", t, glGetError());
        glGetObjectParameterivARB(vs, GL_OBJECT_TYPE_ARB, &t);
        sgl_text(out, "arb", "shader type 0x%04x err 0x%04x\n", t, glGetError());
        glGetObjectParameterivARB(vs, GL_OBJECT_SUBTYPE_ARB, &t);
        sgl_text(out, "arb", "shader subtype 0x%04x err 0x%04x\n", t, glGetError());
        glGetObjectParameterivARB(p, GL_OBJECT_LINK_STATUS_ARB, &t);
        sgl_text(out, "arb", "link status %d err 0x%04x\n", t, glGetError());
        E(glGetObjectParameterivARB(12345, GL_OBJECT_TYPE_ARB, &t));
        glUseProgramObjectARB(p);
        h = glGetHandleARB(GL_PROGRAM_OBJECT_ARB);
        sgl_text(out, "arb", "handle is p %d err 0x%04x\n", h == p, glGetError());
        E(glGetHandleARB(GL_TEXTURE_2D));
        glGetInfoLogARB(vs, sizeof l, &n, l);
        sgl_text(out, "arb", "log (%d) [%s] err 0x%04x\n", n, l, glGetError());
        glUniform1fARB(glGetUniformLocationARB(p, "scale"), 9.5f);
        getf(p, "scale", 1);
        glUseProgramObjectARB(0);
        E(glDeleteObjectARB(12345));
        E(glDeleteObjectARB(vs));
        E(glDeleteObjectARB(fs));
        E(glDeleteObjectARB(p));
        sgl_text(out, "arb", "gone %d %d %d\n", glIsShader(vs), glIsShader(fs), glIsProgram(p));
    }

    return sgl_end_scene(ctx, buf);
}
