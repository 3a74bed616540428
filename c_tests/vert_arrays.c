/* vert_arrays: #version 120 vertex shaders fed by arrays: generic attributes
 * bound with glBindAttribLocation (position at 0 aliasing glVertex, a
 * normalised unsigned-byte colour array, a float with no array read from
 * glVertexAttrib's current value) drawn with glDrawArrays from client memory
 * and with glDrawElements from client indices; built-in arrays (glVertexPointer,
 * glColorPointer, glTexCoordPointer) in a buffer object drawn with
 * glDrawElements from an element buffer as a strip; and a vertex-shader-only
 * program over the same buffer with fixed-function fragments. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS_G =
    "#version 120\n"
    "attribute vec3 pos;\n"
    "attribute vec4 col;\n"
    "attribute float w;\n"
    "uniform vec2 shift;\n"
    "varying vec4 c;\n"
    "varying float d;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(pos.xy + shift, pos.z, 1.0);\n"
    "  c = col;\n"
    "  d = w * pos.x + 0.5;\n"
    "}\n";

static const char *FS_G =
    "#version 120\n"
    "varying vec4 c;\n"
    "varying float d;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(c.rgb * 0.8 + d * 0.2, c.a);\n"
    "}\n";

static const char *VS_B =
    "#version 120\n"
    "varying vec3 t;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = gl_Color;\n"
    "  t = gl_MultiTexCoord0.xyz * vec3(0.5, 0.25, 1.0);\n"
    "}\n";

static const char *FS_B =
    "#version 120\n"
    "varying vec3 t;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(fract(t), 1.0) * 0.5 + gl_Color * 0.5;\n"
    "}\n";

static const char *VS_F =
    "#version 120\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex + vec4(0.3, -0.2, 0.1, 0.0));\n"
    "  gl_FrontColor = vec4(1.0) - gl_Color;\n"
    "}\n";

#define NV 48

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    const char *names[] = {"pos", "col", "w", NULL};
    GLuint g = vert_program(VS_G, FS_G, names);
    GLuint b = vert_program(VS_B, FS_B, NULL);
    GLuint f = vert_program(VS_F, NULL, NULL);
    static float pos[NV][3], tex[NV][2];
    static unsigned char col[NV][4];
    static float fcol[NV][4];
    static GLushort idx[NV];
    GLuint vbo, ebo;
    int i, j;

    for (i = 0; i < NV; i++) {
        pos[i][0] = sgl_randf() * 2.4f - 1.2f;
        pos[i][1] = sgl_randf() * 2.4f - 1.2f;
        pos[i][2] = sgl_randf() * 2.0f - 1.0f;
        tex[i][0] = sgl_randf() * 4.0f - 2.0f;
        tex[i][1] = sgl_randf() * 4.0f - 2.0f;
        for (j = 0; j < 4; j++) {
            col[i][j] = (unsigned char)(sgl_randf() * 255.0f);
            fcol[i][j] = sgl_randf();
        }
        idx[i] = (GLushort)((i * 7) % NV);
    }

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);

    /* generic attributes from client memory */
    glUseProgram(g);
    glUniform2f(glGetUniformLocation(g, "shift"), 0.1f, -0.05f);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, pos);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, col);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glVertexAttrib1f(2, 0.75f);
    glDrawArrays(GL_TRIANGLES, 0, 24);
    glUniform2f(glGetUniformLocation(g, "shift"), -0.2f, 0.15f);
    glVertexAttrib1f(2, -1.5f);
    glDrawElements(GL_QUADS, 24, GL_UNSIGNED_SHORT, idx + 24);
    glDisableVertexAttribArray(0);
    glDisableVertexAttribArray(1);

    /* built-in arrays in a buffer object, indices in an element buffer */
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos + sizeof fcol + sizeof tex, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof pos, pos);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos, sizeof fcol, fcol);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos + sizeof fcol, sizeof tex, tex);
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, (void *)0);
    glColorPointer(4, GL_FLOAT, 0, (void *)sizeof pos);
    glTexCoordPointer(2, GL_FLOAT, 0, (void *)(sizeof pos + sizeof fcol));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glUseProgram(b);
    glDrawElements(GL_TRIANGLE_STRIP, 20, GL_UNSIGNED_SHORT, (void *)0);

    /* a vertex shader alone: fixed-function fragments, blended */
    glUseProgram(f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_TRIANGLES, 24, 24);

    return frag_end(out, "arrays", buf, ctx);
}
