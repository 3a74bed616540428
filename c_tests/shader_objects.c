/* shader_objects: the GL 2.0 shader and program object API against Mesa's,
 * without drawing: glCreateShader/glShaderSource/glCompileShader with
 * glGetShaderiv (type, delete status, compile status, info log and source
 * lengths), glGetShaderSource with short buffers, info logs of a good and a
 * bad shader, program attach/detach/link/validate with glGetProgramiv, the
 * deferred deletion of attached shaders and of the current program,
 * glIsShader/glIsProgram, the link failures of common mistakes with their
 * logs (missing main, two mains, a varying never written, varying and uniform
 * type mismatches, an uncompiled shader), and the GL_INVALID_VALUE /
 * GL_INVALID_OPERATION / GL_INVALID_ENUM cases of every entry point. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "errcheck.h"

static const GLenum SHADER_PNAMES[] = {GL_SHADER_TYPE, GL_DELETE_STATUS, GL_COMPILE_STATUS,
                                       GL_INFO_LOG_LENGTH, GL_SHADER_SOURCE_LENGTH};
static const GLenum PROGRAM_PNAMES[] = {
    GL_DELETE_STATUS,       GL_LINK_STATUS,          GL_VALIDATE_STATUS,
    GL_INFO_LOG_LENGTH,     GL_ATTACHED_SHADERS,     GL_ACTIVE_ATTRIBUTES,
    GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, GL_ACTIVE_UNIFORMS, GL_ACTIVE_UNIFORM_MAX_LENGTH};

static void shader_state(const char *label, GLuint s)
{
    unsigned k;
    for (k = 0; k < sizeof SHADER_PNAMES / sizeof SHADER_PNAMES[0]; k++) {
        GLint v = -7;
        glGetShaderiv(s, SHADER_PNAMES[k], &v);
        sgl_text(out, "shader", "%s pname 0x%04x: %d err 0x%04x\n", label, SHADER_PNAMES[k], v,
                 glGetError());
    }
    sgl_text(out, "shader", "%s is %d err 0x%04x\n", label, glIsShader(s), glGetError());
}

static void program_state(const char *label, GLuint p)
{
    unsigned k;
    for (k = 0; k < sizeof PROGRAM_PNAMES / sizeof PROGRAM_PNAMES[0]; k++) {
        GLint v = -7;
        glGetProgramiv(p, PROGRAM_PNAMES[k], &v);
        sgl_text(out, "program", "%s pname 0x%04x: %d err 0x%04x\n", label, PROGRAM_PNAMES[k],
                 v, glGetError());
    }
    sgl_text(out, "program", "%s is %d err 0x%04x\n", label, glIsProgram(p), glGetError());
}

typedef void (*GetLog)(GLuint, GLsizei, GLsizei *, GLchar *);

static void object_log(const char *label, const char *kind, GLuint obj, GetLog get)
{
    char log[2048];
    GLsizei n = -7;
    memset(log, 0, sizeof log);
    get(obj, sizeof log, &n, log);
    sgl_text(out, "log", "%s %s log (%d) [%s] err 0x%04x\n", label, kind, n, log, glGetError());
}

static void shader_log(const char *label, GLuint s)
{
    object_log(label, "shader", s, glGetShaderInfoLog);
}

static void program_log(const char *label, GLuint p)
{
    object_log(label, "program", p, glGetProgramInfoLog);
}

static GLuint compile(GLenum type, const char *src)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    return s;
}

/* Links a program of the given vertex and fragment sources (NULL: none) and
 * prints its status and log. */
static void link_case(const char *label, const char *vs, const char *vs2, const char *fs)
{
    GLuint p = glCreateProgram();
    GLuint s[3] = {0, 0, 0};
    GLint ok = -7, n = -7, i;
    if (vs)
        s[0] = compile(GL_VERTEX_SHADER, vs);
    if (vs2)
        s[1] = compile(GL_VERTEX_SHADER, vs2);
    if (fs)
        s[2] = compile(GL_FRAGMENT_SHADER, fs);
    for (i = 0; i < 3; i++)
        if (s[i])
            glAttachShader(p, s[i]);
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    glGetProgramiv(p, GL_INFO_LOG_LENGTH, &n);
    sgl_text(out, "link", "%s status %d log length %d err 0x%04x\n", label, ok, n,
             glGetError());
    program_log(label, p);
    glDeleteProgram(p);
    for (i = 0; i < 3; i++)
        if (s[i])
            glDeleteShader(s[i]);
}

/* Links vs and fs and prints the active uniforms and attributes (sorted by
 * name) with their locations: Mesa's attribute assignment (largest first,
 * lowest free slots, generic 0 kept for gl_Vertex), array shortening, what
 * counts as active. */
static void interface_case(const char *label, const char *vs, const char *fs)
{
    GLuint p = glCreateProgram();
    GLuint s[2] = {0, 0};
    static char lines[32][160];
    GLint ok = -7, n = 0, i, which;
    s[0] = compile(GL_VERTEX_SHADER, vs);
    glAttachShader(p, s[0]);
    if (fs) {
        s[1] = compile(GL_FRAGMENT_SHADER, fs);
        glAttachShader(p, s[1]);
    }
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    sgl_text(out, "iface", "%s: link %d\n", label, ok);
    for (which = 0; which < 2; which++) {
        glGetProgramiv(p, which ? GL_ACTIVE_UNIFORMS : GL_ACTIVE_ATTRIBUTES, &n);
        SGL_CHECK(n <= 32);
        for (i = 0; i < n; i++) {
            char name[64] = "";
            GLint size = -7;
            GLenum type = 0;
            if (which) {
                glGetActiveUniform(p, i, sizeof name, NULL, &size, &type, name);
                snprintf(lines[i], sizeof lines[i], "uniform %s size %d type 0x%04x loc %s",
                         name, size, type,
                         glGetUniformLocation(p, name) >= 0 ? "found" : "none");
            } else {
                glGetActiveAttrib(p, i, sizeof name, NULL, &size, &type, name);
                snprintf(lines[i], sizeof lines[i], "attrib %s size %d type 0x%04x loc %d", name,
                         size, type, glGetAttribLocation(p, name));
            }
        }
        qsort(lines, (size_t)n, sizeof lines[0], by_name);
        for (i = 0; i < n; i++)
            sgl_text(out, "iface", "  %s\n", lines[i]);
    }
    sgl_text(out, "iface", "  err 0x%04x\n", glGetError());
    glDeleteProgram(p);
    glDeleteShader(s[0]);
    if (s[1])
        glDeleteShader(s[1]);
}

static const char *VS = "void main() { gl_Position = gl_Vertex; }\n";
static const char *FS = "void main() { gl_FragColor = vec4(1.0); }\n";

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    void *buf;
    GLuint vs, fs, bad, p, p2, got[4];
    GLsizei count;
    char text[256];
    GLsizei n;
    GLint v;
    const char *parts[3] = {"void main() {", " gl_Position = gl_Vertex; (not read)", "}\n"};
    GLint lens[3] = {-1, 26, 2};

    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx);
    buf = malloc(16 * 16 * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16));

    /* a shader's life */
    vs = glCreateShader(GL_VERTEX_SHADER);
    sgl_text(out, "create", "vs nonzero %d err 0x%04x\n", vs != 0, glGetError());
    shader_state("vs fresh", vs);
    shader_log("vs fresh", vs);
    glShaderSource(vs, 1, &VS, NULL);
    shader_state("vs sourced", vs);
    memset(text, 0, sizeof text);
    n = -7;
    glGetShaderSource(vs, sizeof text, &n, text);
    sgl_text(out, "source", "full (%d) [%s] err 0x%04x\n", n, text, glGetError());
    memset(text, 0, sizeof text);
    glGetShaderSource(vs, 5, &n, text);
    sgl_text(out, "source", "short (%d) [%s] err 0x%04x\n", n, text, glGetError());
    memset(text, 'x', sizeof text);
    text[255] = 0;
    glGetShaderSource(vs, 0, &n, text);
    sgl_text(out, "source", "zero (%d) [%.4s] err 0x%04x\n", n, text, glGetError());
    glCompileShader(vs);
    shader_state("vs compiled", vs);
    shader_log("vs compiled", vs);

    /* sources in parts, with explicit and -1 lengths */
    fs = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(fs, 3, parts, lens);
    memset(text, 0, sizeof text);
    glGetShaderSource(fs, sizeof text, &n, text);
    sgl_text(out, "source", "parts (%d) [%s] err 0x%04x\n", n, text, glGetError());
    glCompileShader(fs);
    shader_state("parts compiled", fs);
    glDeleteShader(fs);

    fs = compile(GL_FRAGMENT_SHADER, FS);
    shader_state("fs compiled", fs);

    bad = compile(GL_FRAGMENT_SHADER, "void main() {\n  gl_FragColor = 1;\n}\n");
    shader_state("bad", bad);
    shader_log("bad", bad);
    /* a short log buffer: truncated and NUL-terminated */
    memset(text, 0, sizeof text);
    n = -7;
    glGetShaderInfoLog(bad, 6, &n, text);
    sgl_text(out, "log", "short (%d) [%s] err 0x%04x\n", n, text, glGetError());

    /* programs */
    p = glCreateProgram();
    sgl_text(out, "create", "program nonzero %d distinct %d err 0x%04x\n", p != 0,
             p != vs && p != fs, glGetError());
    program_state("p fresh", p);
    program_log("p fresh", p);
    E(glAttachShader(p, vs));
    E(glAttachShader(p, vs));
    E(glAttachShader(p, fs));
    glGetAttachedShaders(p, 4, &count, got);
    sgl_text(out, "attached", "%d: %d %d\n", count, got[0] == vs || got[1] == vs,
             got[0] == fs || got[1] == fs);
    count = -7;
    got[0] = 12345;
    glGetAttachedShaders(p, 1, &count, got);
    sgl_text(out, "attached", "max 1: %d first is vs %d err 0x%04x\n", count, got[0] == vs,
             glGetError());
    E(glGetAttachedShaders(p, -1, &count, got));
    glLinkProgram(p);
    program_state("p linked", p);
    program_log("p linked", p);
    glValidateProgram(p);
    program_state("p validated", p);

    /* deleting an attached shader only marks it */
    E(glDeleteShader(vs));
    shader_state("vs deleted while attached", vs);
    E(glUseProgram(p));
    glGetIntegerv(GL_CURRENT_PROGRAM, &v);
    sgl_text(out, "current", "is p %d err 0x%04x\n", v == (GLint)p, glGetError());
    E(glDeleteProgram(p));
    program_state("p deleted while current", p);
    shader_state("vs after program delete", vs);
    E(glUseProgram(0));
    glGetIntegerv(GL_CURRENT_PROGRAM, &v);
    sgl_text(out, "current", "after use 0: %d err 0x%04x\n", v, glGetError());
    sgl_text(out, "gone", "p %d vs %d fs %d err 0x%04x\n", glIsProgram(p), glIsShader(vs),
             glIsShader(fs), glGetError());

    /* detach */
    p2 = glCreateProgram();
    E(glAttachShader(p2, fs));
    E(glDetachShader(p2, fs));
    E(glDetachShader(p2, fs));
    E(glDetachShader(p2, bad));
    program_state("p2 after detach", p2);
    glLinkProgram(p2);
    program_state("p2 linked empty", p2);
    program_log("p2 linked empty", p2);

    /* errors */
    E(glCreateShader(GL_TEXTURE_2D));
    E(glCreateShader(0));
    E(glShaderSource(12345, 1, &VS, NULL));
    E(glShaderSource(p2, 1, &VS, NULL));
    E(glShaderSource(fs, -1, &VS, NULL));
    E(glCompileShader(12345));
    E(glCompileShader(p2));
    E(glGetShaderiv(fs, GL_LINK_STATUS, &v));
    E(glGetShaderiv(fs, 0, &v));
    E(glGetShaderiv(p2, GL_COMPILE_STATUS, &v));
    E(glGetShaderiv(12345, GL_COMPILE_STATUS, &v));
    E(glGetProgramiv(fs, GL_LINK_STATUS, &v));
    E(glGetProgramiv(p2, GL_COMPILE_STATUS, &v));
    E(glGetProgramiv(12345, GL_LINK_STATUS, &v));
    E(glGetShaderInfoLog(fs, -1, &n, text));
    E(glGetShaderInfoLog(p2, 10, &n, text));
    E(glGetProgramInfoLog(p2, -1, &n, text));
    E(glGetProgramInfoLog(fs, 10, &n, text));
    E(glGetShaderSource(fs, -1, &n, text));
    E(glGetShaderSource(p2, 10, &n, text));
    E(glAttachShader(p2, p2));
    E(glAttachShader(fs, fs));
    E(glAttachShader(12345, fs));
    E(glAttachShader(p2, 12345));
    E(glDetachShader(12345, fs));
    E(glDetachShader(p2, 12345));
    E(glDetachShader(fs, fs));
    E(glLinkProgram(12345));
    E(glLinkProgram(fs));
    E(glValidateProgram(12345));
    E(glValidateProgram(fs));
    E(glUseProgram(12345));
    E(glUseProgram(fs));
    E(glDeleteShader(12345));
    E(glDeleteShader(p2));
    E(glDeleteShader(0));
    E(glDeleteProgram(12345));
    E(glDeleteProgram(fs));
    E(glDeleteProgram(0));
    E(glGetAttachedShaders(fs, 4, &count, got));
    E(glGetAttachedShaders(12345, 4, &count, got));
    sgl_text(out, "is", "0: %d %d, bogus %d %d\n", glIsShader(0), glIsProgram(0),
             glIsShader(12345), glIsProgram(12345));
    sgl_text(out, "is", "crossed: %d %d err 0x%04x\n", glIsShader(p2), glIsProgram(fs),
             glGetError());
    /* a program that failed to link cannot be made current */
    {
        GLuint pb = glCreateProgram();
        glAttachShader(pb, bad);
        glLinkProgram(pb);
        glGetProgramiv(pb, GL_LINK_STATUS, &v);
        sgl_text(out, "link", "with bad shader %d\n", v);
        E(glUseProgram(pb));
        glGetIntegerv(GL_CURRENT_PROGRAM, &v);
        sgl_text(out, "current", "after failed use %d\n", v);
        glDeleteProgram(pb);
    }
    glDeleteShader(fs);
    glDeleteShader(bad);
    glDeleteProgram(p2);

    /* link failures and their logs */
    link_case("ok", VS, NULL, FS);
    link_case("vertex only", VS, NULL, NULL);
    link_case("fragment only", NULL, NULL, FS);
    link_case("no vertex main", "float f() { return 1.0; }\n", NULL, FS);
    link_case("no fragment main", VS, NULL, "float f() { return 1.0; }\n");
    link_case("two vertex mains", VS, VS, FS);
    link_case("two shaders one main", "float f(); void main() { gl_Position = gl_Vertex * f(); }\n",
              "float f() { return 2.0; }\n", FS);
    link_case("unresolved function", "float f(); void main() { gl_Position = gl_Vertex * f(); }\n",
              NULL, FS);
    link_case("varying type",
              "varying vec3 c; void main() { c = vec3(1.0); gl_Position = gl_Vertex; }\n", NULL,
              "varying vec4 c; void main() { gl_FragColor = c; }\n");
    link_case("varying array size",
              "varying float c[2]; void main() { c[0] = 1.0; c[1] = 1.0; gl_Position = gl_Vertex; }\n",
              NULL, "varying float c[3]; void main() { gl_FragColor = vec4(c[0]); }\n");
    link_case("varying unused unwritten", VS, NULL,
              "varying vec4 c; void main() { gl_FragColor = vec4(1.0); }\n");
    link_case("uniform type",
              "uniform vec3 u; void main() { gl_Position = gl_Vertex + u.x; }\n", NULL,
              "uniform vec4 u; void main() { gl_FragColor = u; }\n");
    link_case("uniform array size",
              "uniform float u[2]; void main() { gl_Position = gl_Vertex * u[1]; }\n", NULL,
              "uniform float u[3]; void main() { gl_FragColor = vec4(u[2]); }\n");
    link_case("uniform same",
              "uniform vec4 u; void main() { gl_Position = gl_Vertex + u; }\n", NULL,
              "uniform vec4 u; void main() { gl_FragColor = u; }\n");
    link_case("uncompiled", "void main() { gl_Position = 1; }\n", NULL, FS);
    link_case("versions 120 and 110", "#version 120\nvoid main() { gl_Position = gl_Vertex; }\n",
              NULL, FS);

    interface_case("ftransform", "void main() { gl_Position = ftransform(); gl_FrontColor = gl_Color; }\n",
                   "void main() { gl_FragColor = gl_Color; }\n");
    interface_case("gl_Vertex keeps generic 0",
                   "attribute vec4 a; attribute vec4 b;\n"
                   "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex + a + b + gl_MultiTexCoord1; }\n",
                   NULL);
    interface_case("generic only", "attribute vec4 a; attribute vec4 b; void main() { gl_Position = a + b; }\n",
                   NULL);
    interface_case("largest first",
                   "attribute vec4 a; attribute mat4 m; attribute vec2 b; attribute mat2 m2;\n"
                   "void main() { gl_Position = m * a + b.xyxy + m2[1].xyxy; }\n",
                   NULL);
    interface_case("dynamic index", "uniform float u[4]; uniform int k; void main() { gl_Position = vec4(u[k]); }\n",
                   NULL);
    interface_case("struct array shortened",
                   "struct S { float f; vec2 g; }; uniform S s[3]; void main() { gl_Position = vec4(s[1].f); }\n",
                   NULL);
    interface_case("unused function", "uniform vec4 u; float f() { return u.x; } void main() { gl_Position = vec4(1.0); }\n",
                   NULL);
    interface_case("dead branch",
                   "uniform vec4 u; void main() { gl_Position = vec4(1.0); if (false) gl_Position = u; }\n",
                   NULL);
    interface_case("called function",
                   "uniform vec4 u; uniform mat2 m; vec4 f() { return u * m[0].x; } void main() { gl_Position = f(); }\n",
                   "uniform sampler2D t; uniform samplerCube c; uniform sampler1DShadow sh;\n"
                   "void main() { gl_FragColor = texture2D(t, vec2(0.0)) + textureCube(c, vec3(1.0)) + shadow1D(sh, vec3(0.5)); }\n");

    return sgl_end_scene(ctx, buf);
}
