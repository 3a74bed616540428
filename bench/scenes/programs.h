/*
 * programs.h - GLSL programs for the benchmark scenes that draw with shaders.
 *
 * Include after <GL/gl.h> and <GL/glext.h> (with GL_GLEXT_PROTOTYPES) and bench.h.
 */
#ifndef SGL_BENCH_PROGRAMS_H
#define SGL_BENCH_PROGRAMS_H

/* A compiled shader of `kind`; prints the log and exits on failure. */
static GLuint program_shader(GLenum kind, const char *src)
{
    GLuint s = glCreateShader(kind);
    GLint ok = 0;
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "compile: %s\n", log);
        exit(2);
    }
    return s;
}

/* The linked program of vertex shader `vs` and fragment shader `fs`, made current;
 * exits on failure. */
static GLuint program_use(const char *vs, const char *fs)
{
    GLuint prog = glCreateProgram();
    GLint ok = 0;
    glAttachShader(prog, program_shader(GL_VERTEX_SHADER, vs));
    glAttachShader(prog, program_shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(prog);
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        fprintf(stderr, "link failed\n");
        exit(2);
    }
    glUseProgram(prog);
    return prog;
}

#endif
