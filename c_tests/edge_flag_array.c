/* edge_flag_array: glEdgeFlagPointer with GL_EDGE_FLAG_ARRAY hiding interior
 * edges of polygons drawn in GL_LINE and GL_POINT mode through glDrawArrays,
 * glDrawElements and glArrayElement (also compiled into a display list); a
 * strided edge-flag array; glGet of the state, glGetPointerv, glIsEnabled and
 * glPushClientAttrib/glPopClientAttrib; glInterleavedArrays disabling it. */
#include "prims_common.h"

typedef struct {
    GLfloat x, y;
    GLboolean e;
    GLubyte pad[3];
} Vtx;

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    /* a hexagon as a fan of 4 triangles: only the outline edges are flagged */
    static GLfloat hex[12 * 2];
    static GLboolean hexflags[12];
    static Vtx packed[8];
    static const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
    GLint stride = -1, enabled = -1, after_pop = -1, after_il = -1;
    GLboolean isen;
    GLvoid *ptr = NULL;
    GLuint list;
    int i;
    prims_begin();
    for (i = 0; i < 4; i++) {
        /* triangle (c, p_i, p_i+1) of the fan: edges c-p_i, p_i-p_i+1, p_i+1-c */
        float a0 = 1.0471976f * (float)i, a1 = 1.0471976f * (float)(i + 1);
        hex[6 * i + 0] = 60.0f;
        hex[6 * i + 1] = 60.0f;
        hex[6 * i + 2] = 60.0f + 45.0f * cosf(a0);
        hex[6 * i + 3] = 60.0f + 45.0f * sinf(a0);
        hex[6 * i + 4] = 60.0f + 45.0f * cosf(a1);
        hex[6 * i + 5] = 60.0f + 45.0f * sinf(a1);
        hexflags[3 * i + 0] = (GLboolean)(i == 0);
        hexflags[3 * i + 1] = GL_TRUE;
        hexflags[3 * i + 2] = (GLboolean)(i == 3);
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, hex);
    glEdgeFlagPointer(0, hexflags);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glGetIntegerv(GL_EDGE_FLAG_ARRAY, &enabled);
    glGetIntegerv(GL_EDGE_FLAG_ARRAY_STRIDE, &stride);
    glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &ptr);
    isen = glIsEnabled(GL_EDGE_FLAG_ARRAY);
    sgl_text(out, "state", "enabled %d stride %d ptr_ok %d isen %d err 0x%x\n", enabled, stride,
             ptr == (GLvoid *)hexflags, isen, glGetError());

    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1.0f, 0.8f, 0.2f);
    glDrawArrays(GL_TRIANGLES, 0, 12);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3.0f);
    glPushMatrix();
    glTranslatef(120.0f, 0.0f, 0.0f);
    glColor3f(0.3f, 1.0f, 0.6f);
    glDrawArrays(GL_TRIANGLES, 0, 12);
    glPopMatrix();

    /* a quad as two indexed triangles from a strided, interleaved array */
    for (i = 0; i < 4; i++) {
        packed[i].x = (i == 1 || i == 2) ? 100.0f : 10.0f;
        packed[i].y = (i >= 2) ? 230.0f : 130.0f;
        packed[i].e = GL_TRUE;
    }
    packed[2].e = GL_FALSE; /* edge 2->0 of the first triangle is the diagonal */
    packed[0].e = GL_TRUE;
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(2.0f);
    glVertexPointer(2, GL_FLOAT, sizeof(Vtx), &packed[0].x);
    glEdgeFlagPointer(sizeof(Vtx), &packed[0].e);
    glGetIntegerv(GL_EDGE_FLAG_ARRAY_STRIDE, &stride);
    glColor3f(0.4f, 0.6f, 1.0f);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);

    /* glArrayElement, immediate and compiled */
    glPushMatrix();
    glTranslatef(120.0f, 0.0f, 0.0f);
    glColor3f(1.0f, 0.4f, 0.7f);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++)
        glArrayElement(idx[i]);
    glEnd();
    glTranslatef(0.0f, -10.0f, 0.0f);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++)
        glArrayElement(idx[i]);
    glEnd();
    glEndList();
    packed[2].e = GL_TRUE; /* the list keeps the flags read at compile time */
    glColor3f(0.9f, 0.9f, 0.9f);
    glTranslatef(10.0f, 5.0f, 0.0f);
    glCallList(list);
    glPopMatrix();

    /* push/pop client attrib and glInterleavedArrays */
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glEdgeFlagPointer(0, hexflags);
    glPopClientAttrib();
    glGetIntegerv(GL_EDGE_FLAG_ARRAY, &after_pop);
    glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &ptr);
    sgl_text(out, "pop", "enabled %d stride %d ptr_ok %d err 0x%x\n", after_pop, stride,
             ptr == (GLvoid *)&packed[0].e, glGetError());
    glEdgeFlagPointer(-1, hexflags);
    sgl_text(out, "negative_stride", "0x%x\n", glGetError());
    glInterleavedArrays(GL_V2F, 0, hex);
    glGetIntegerv(GL_EDGE_FLAG_ARRAY, &after_il);
    sgl_text(out, "interleaved", "%d\n", after_il);
    /* without the array: all edges drawn */
    glColor3f(0.6f, 0.6f, 0.6f);
    glPushMatrix();
    glTranslatef(0.0f, 120.0f, 0.0f);
    glScalef(0.5f, 0.5f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 12);
    glPopMatrix();
    prims_end(out, "edges");
    prims_close(out);
    return 0;
}
