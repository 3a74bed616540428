/*
 * sphere_buffers.h - one sphere mesh in buffer objects, for the scenes that draw it many
 * times with glDrawElements (vbo_draws, uniform_draws).
 *
 * Include after <GL/gl.h>, <GL/glext.h> (with GL_GLEXT_PROTOTYPES) and shapes.h.
 */
#ifndef SGL_BENCH_SPHERE_BUFFERS_H
#define SGL_BENCH_SPHERE_BUFFERS_H

#define SPHERE_SLICES 24
#define SPHERE_STACKS 16
/* Indices of the mesh: 24 x 16 quads as 768 triangles. */
#define SPHERE_NIDX (SPHERE_SLICES * SPHERE_STACKS * 6)

/* Uploads the unit sphere (shape_sphere_arrays) into a GL_ARRAY_BUFFER, `stride` floats a
 * vertex (6: position and normal; 8: and texture coordinates), and its 16-bit indices
 * into a GL_ELEMENT_ARRAY_BUFFER, both left bound, and points and enables the vertex,
 * normal and (with 8) texture coordinate arrays at them. */
static void sphere_buffers(int stride)
{
    static GLfloat verts[(SPHERE_SLICES + 1) * (SPHERE_STACKS + 1) * 8];
    static GLushort idx[SPHERE_NIDX];
    GLsizei bytes = (GLsizei)sizeof(GLfloat) * stride;
    GLuint bufs[2];
    shape_sphere_arrays(verts, stride, idx, SPHERE_SLICES, SPHERE_STACKS);
    glGenBuffers(2, bufs);
    glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
    glBufferData(GL_ARRAY_BUFFER,
                 (GLsizeiptr)bytes * (SPHERE_SLICES + 1) * (SPHERE_STACKS + 1), verts,
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(idx), idx, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, bytes, (const GLvoid *)0);
    glNormalPointer(GL_FLOAT, bytes, (const GLvoid *)12);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    if (stride >= 8) {
        glTexCoordPointer(2, GL_FLOAT, bytes, (const GLvoid *)24);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    }
}

#endif
