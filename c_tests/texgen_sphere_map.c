/* texgen_sphere_map: GL_SPHERE_MAP, GL_REFLECTION_MAP and GL_NORMAL_MAP
 * texture coordinate generation, seen through a 2D checker texture (the
 * reflection and normal vectors are mapped from [-1,1] to [0,1] with a
 * texture matrix).  Spheres and tori in perspective, with GL_NORMALIZE,
 * GL_RESCALE_NORMAL, a non-uniform modelview scale, lighting, and
 * un-normalised normals. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"
#include "texgen_common.h"

#define W 256
#define H 256

static void cell(int i)
{
    glViewport((i % 3) * 85, (i / 3) * 85, 85, 85);
}

static void gen(GLenum mode)
{
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
}

static void unit_matrix(int on)
{
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    if (on) {
        glTranslatef(0.5f, 0.5f, 0.0f);
        glScalef(0.5f, 0.5f, 1.0f);
    }
    glMatrixMode(GL_MODELVIEW);
}

static void place(float ax, float ay, float angle)
{
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(angle, ax, ay, 0.3f);
}

int main(int argc, char **argv)
{
    static const unsigned char a[4] = {250, 240, 40, 255}, b[4] = {30, 90, 170, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(32, 32, 4, 4, a, b);
    GLuint tex;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);

    /* 0: sphere map on a sphere */
    cell(0);
    gen(GL_SPHERE_MAP);
    place(1.0f, 0.0f, 20.0f);
    sgl_sphere(1.0f, 24, 16);

    /* 1: sphere map on a torus, off-centre so the eye vector varies */
    cell(1);
    glLoadIdentity();
    glTranslatef(0.4f, -0.3f, -3.0f);
    glRotatef(60.0f, 1.0f, 0.2f, 0.0f);
    sgl_torus(0.8f, 0.3f, 24, 12);

    /* 2: sphere map, non-uniform scale with GL_NORMALIZE */
    cell(2);
    glEnable(GL_NORMALIZE);
    place(0.0f, 1.0f, 35.0f);
    glScalef(1.3f, 0.8f, 1.0f);
    sgl_sphere(1.0f, 24, 16);
    glDisable(GL_NORMALIZE);

    /* 3: reflection map */
    cell(3);
    gen(GL_REFLECTION_MAP);
    unit_matrix(1);
    place(1.0f, 1.0f, 30.0f);
    sgl_sphere(1.0f, 24, 16);

    /* 4: reflection map with GL_RESCALE_NORMAL and a uniform scale */
    cell(4);
    glEnable(GL_RESCALE_NORMAL);
    place(0.3f, 1.0f, 80.0f);
    glScalef(0.7f, 0.7f, 0.7f);
    sgl_torus(1.1f, 0.45f, 24, 12);
    glDisable(GL_RESCALE_NORMAL);

    /* 5: normal map, S and T, R generated too */
    cell(5);
    gen(GL_NORMAL_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    glEnable(GL_TEXTURE_GEN_R);
    place(1.0f, 0.4f, 45.0f);
    sgl_torus(0.8f, 0.3f, 24, 12);
    glDisable(GL_TEXTURE_GEN_R);

    /* 6: normal map with un-normalised normals and a non-uniform scale */
    cell(6);
    place(0.2f, 1.0f, 10.0f);
    glScalef(1.0f, 1.4f, 0.9f);
    glBegin(GL_TRIANGLES);
    glNormal3f(2.0f, 0.5f, 1.0f);
    glVertex3f(-1.0f, -1.0f, 0.0f);
    glNormal3f(-0.3f, 1.7f, 0.4f);
    glVertex3f(1.0f, -0.8f, 0.2f);
    glNormal3f(0.1f, -0.2f, 3.0f);
    glVertex3f(0.0f, 1.0f, -0.3f);
    glEnd();

    /* 7: mixed: S sphere map, T reflection map, with lighting */
    cell(7);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    unit_matrix(0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    place(1.0f, 0.0f, -30.0f);
    sgl_sphere(1.0f, 24, 16);
    glDisable(GL_LIGHTING);

    /* 8: sphere map through a second texture unit, unit 0 plain */
    cell(8);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    gen(GL_SPHERE_MAP);
    glActiveTexture(GL_TEXTURE0);
    glMultiTexCoord2f(GL_TEXTURE0, 0.2f, 0.7f);
    place(0.5f, 1.0f, 50.0f);
    sgl_torus(0.8f, 0.3f, 24, 12);

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    free(checker);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
