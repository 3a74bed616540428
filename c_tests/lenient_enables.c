/* lenient_enables: glEnable/glDisable/glIsEnabled with the client arrays
 * (GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY,
 * GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY, GL_FOG_COORDINATE_ARRAY,
 * GL_SECONDARY_COLOR_ARRAY), which Mesa's compatibility profile takes as
 * glEnableClientState/glDisableClientState: the states and errors read back,
 * draws with arrays enabled that way, glEnable(GL_COLOR_ARRAY) compiled into a
 * display list (applied when the list is called), and inside glBegin/glEnd. */
#include "prims_common.h"
#include <GL/glext.h>

static const GLenum caps[8] = {
    GL_VERTEX_ARRAY,         GL_NORMAL_ARRAY,    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,          GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY,
    GL_FOG_COORDINATE_ARRAY, GL_SECONDARY_COLOR_ARRAY,
};

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const GLfloat tri[6] = {20.0f, 20.0f, 120.0f, 30.0f, 40.0f, 120.0f};
    static const GLfloat col[12] = {1.0f, 0.2f, 0.1f, 1.0f, 0.1f, 0.9f,
                                    0.3f, 1.0f, 0.2f, 0.4f, 1.0f, 1.0f};
    GLint geti;
    GLuint list;
    int i;
    prims_begin();
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glColorPointer(4, GL_FLOAT, 0, col);

    /* Each array enabled and disabled through glEnable/glDisable. */
    for (i = 0; i < 8; i++) {
        GLboolean on, off;
        GLenum e1, e2;
        glEnable(caps[i]);
        e1 = glGetError();
        on = glIsEnabled(caps[i]);
        glGetIntegerv(caps[i], &geti);
        glDisable(caps[i]);
        e2 = glGetError();
        off = glIsEnabled(caps[i]);
        sgl_text(out, "states", "cap 0x%x: enable err 0x%x isen %d get %d; disable err 0x%x isen %d\n",
                 caps[i], e1, on, geti, e2, off);
    }

    /* Drawing with arrays enabled that way. */
    glEnable(GL_VERTEX_ARRAY);
    glEnable(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_COLOR_ARRAY);
    glColor3f(0.9f, 0.9f, 0.2f);
    glTranslatef(120.0f, 0.0f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* Compiled into a display list: applied when the list is called. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEnable(GL_COLOR_ARRAY);
    glEndList();
    sgl_text(out, "list", "after compile isen %d err 0x%x\n", glIsEnabled(GL_COLOR_ARRAY),
             glGetError());
    glCallList(list);
    sgl_text(out, "list", "after call isen %d err 0x%x\n", glIsEnabled(GL_COLOR_ARRAY),
             glGetError());
    glTranslatef(-120.0f, 120.0f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* Inside glBegin/glEnd. */
    glBegin(GL_POINTS);
    glEnable(GL_NORMAL_ARRAY);
    glEnd();
    sgl_text(out, "begin_end", "err 0x%x isen %d\n", glGetError(), glIsEnabled(GL_NORMAL_ARRAY));

    /* An enum that is neither a capability nor an array stays an error. */
    glEnable(GL_VERTEX_ARRAY_POINTER);
    sgl_text(out, "bad", "err 0x%x\n", glGetError());

    prims_end(out, "color");
    prims_close(out);
    return 0;
}
