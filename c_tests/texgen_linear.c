/* texgen_linear: GL_OBJECT_LINEAR and GL_EYE_LINEAR texture coordinate
 * generation.  A stripe texture on spheres and tori in perspective: object
 * linear S (plane tilted), object linear S and T with a checker, eye linear
 * with the eye plane specified under a rotated modelview (so it is moved to
 * eye space at that moment), an eye plane given under the identity, R/Q
 * generation feeding a projective lookup, and texgen combined with a texture
 * matrix and with lighting.  glGetTexGen values are dumped. */
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

int main(int argc, char **argv)
{
    static const unsigned char a[4] = {240, 200, 30, 255}, b[4] = {20, 60, 200, 255};
    static const GLfloat splane[4] = {1.3f, 0.4f, 0.2f, 0.5f};
    static const GLfloat tplane[4] = {0.1f, 1.7f, -0.3f, 0.25f};
    static const GLfloat eplane[4] = {0.9f, -0.6f, 0.35f, 0.1f};
    static const GLint iplane[4] = {2, 0, 1, 3};
    static const GLdouble dplane[4] = {0.25, 0.5, 0.75, 1.0};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex;
    GLfloat f[4];
    GLint iv[4];
    GLdouble d[4];
    char text[2048];
    int n = 0;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    sgl_stripe_texture(8, a, b);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);

    /* 0: object linear S on a sphere */
    cell(0);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(30.0f, 1.0f, 0.5f, 0.0f);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, splane);
    glEnable(GL_TEXTURE_GEN_S);
    sgl_sphere(1.0f, 24, 16);

    /* 1: object linear S and T on a torus */
    cell(1);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, tplane);
    glEnable(GL_TEXTURE_GEN_T);
    sgl_torus(0.8f, 0.3f, 24, 12);

    /* 2: eye linear, plane given under a rotated, scaled modelview */
    cell(2);
    glLoadIdentity();
    glRotatef(40.0f, 0.3f, 1.0f, 0.2f);
    glScalef(1.5f, 0.7f, 1.1f);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, eplane);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeniv(GL_T, GL_EYE_PLANE, iplane);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(-25.0f, 0.0f, 1.0f, 0.0f);
    sgl_sphere(1.0f, 24, 16);

    /* 3: same planes, the object rotating under them (eye linear stays put) */
    cell(3);
    glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
    sgl_torus(0.8f, 0.3f, 24, 12);

    /* 4: eye plane given under the identity, double version, plus texture matrix */
    cell(4);
    glLoadIdentity();
    glTexGendv(GL_S, GL_EYE_PLANE, dplane);
    glTexGend(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glScalef(3.0f, 2.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.1f, -0.1f, -3.2f);
    glRotatef(15.0f, 1.0f, 1.0f, 0.0f);
    sgl_sphere(1.0f, 20, 14);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);

    /* 5: R and Q generated, Q feeding the projective divide */
    cell(5);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    f[0] = 0.0f, f[1] = 0.3f, f[2] = 0.0f, f[3] = 1.0f;
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, f);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_GEN_R);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(50.0f, 0.2f, 1.0f, 0.0f);
    sgl_torus(0.8f, 0.35f, 20, 10);
    glDisable(GL_TEXTURE_GEN_Q);
    glDisable(GL_TEXTURE_GEN_R);

    /* 6: texgen with lighting (eye linear moves lighting to eye space) */
    cell(6);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, eplane);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glScalef(1.2f, 1.0f, 0.8f);
    sgl_sphere(1.0f, 24, 16);
    glDisable(GL_LIGHTING);

    /* 7: generation enabled on a unit whose texturing is off does nothing */
    cell(7);
    glDisable(GL_TEXTURE_2D);
    glColor3f(0.6f, 0.2f, 0.8f); /* x255 is integral: constant colours are uniforms in Mesa */
    sgl_torus(0.8f, 0.3f, 16, 8);
    glEnable(GL_TEXTURE_2D);

    /* 8: only T generated; S from glTexCoord */
    cell(8);
    glDisable(GL_TEXTURE_GEN_S);
    glTexCoord2f(0.3f, 0.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    sgl_sphere(1.0f, 24, 16);

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* queries */
    glGetTexGenfv(GL_S, GL_EYE_PLANE, f);
    n += snprintf(text + n, sizeof text - n, "eyeS %.9g %.9g %.9g %.9g\n", f[0], f[1], f[2], f[3]);
    glGetTexGendv(GL_T, GL_EYE_PLANE, d);
    n += snprintf(text + n, sizeof text - n, "eyeT %.17g %.17g %.17g %.17g\n", d[0], d[1], d[2], d[3]);
    glGetTexGeniv(GL_T, GL_OBJECT_PLANE, iv);
    n += snprintf(text + n, sizeof text - n, "objT %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
    glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, iv);
    n += snprintf(text + n, sizeof text - n, "modeR %x\n", iv[0]);
    glGetTexGenfv(GL_Q, GL_TEXTURE_GEN_MODE, f);
    n += snprintf(text + n, sizeof text - n, "modeQ %g\n", f[0]);
    glGetTexGendv(GL_R, GL_OBJECT_PLANE, d);
    n += snprintf(text + n, sizeof text - n, "objR %g %g %g %g\n", d[0], d[1], d[2], d[3]);
    n += snprintf(text + n, sizeof text - n, "enabled %d %d %d %d\n", glIsEnabled(GL_TEXTURE_GEN_S),
                  glIsEnabled(GL_TEXTURE_GEN_T), glIsEnabled(GL_TEXTURE_GEN_R), glIsEnabled(GL_TEXTURE_GEN_Q));
    glActiveTexture(GL_TEXTURE1);
    n += snprintf(text + n, sizeof text - n, "unit1 T %d\n", glIsEnabled(GL_TEXTURE_GEN_T));
    glGetTexGenfv(GL_S, GL_OBJECT_PLANE, f);
    n += snprintf(text + n, sizeof text - n, "unit1 objS %g %g %g %g\n", f[0], f[1], f[2], f[3]);
    glActiveTexture(GL_TEXTURE0);
    n += snprintf(text + n, sizeof text - n, "unit0 T %d\n", glIsEnabled(GL_TEXTURE_GEN_T));
    /* errors */
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    n += snprintf(text + n, sizeof text - n, "sphere on R %x\n", glGetError());
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    n += snprintf(text + n, sizeof text - n, "normal on Q %x\n", glGetError());
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR);
    n += snprintf(text + n, sizeof text - n, "bad mode %x\n", glGetError());
    glTexGeni(GL_S + 7, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    n += snprintf(text + n, sizeof text - n, "bad coord %x\n", glGetError());
    glTexGenf(GL_S, GL_TEXTURE_ENV_MODE, 1.0f);
    n += snprintf(text + n, sizeof text - n, "bad pname %x\n", glGetError());
    glTexGenf(GL_S, GL_OBJECT_PLANE, 3.0f);
    glGetTexGenfv(GL_S, GL_OBJECT_PLANE, f);
    n += snprintf(text + n, sizeof text - n, "scalar plane %x %g %g %g %g\n", glGetError(), f[0], f[1], f[2], f[3]);
    glGetTexGeniv(GL_S, GL_EYE_LINEAR, iv);
    n += snprintf(text + n, sizeof text - n, "bad get %x\n", glGetError());
    glBegin(GL_TRIANGLES);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnd();
    n += snprintf(text + n, sizeof text - n, "in begin %x\n", glGetError());
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, iv);
    n += snprintf(text + n, sizeof text - n, "mode S %x\n", iv[0]);
    sgl_text(out, "state", "%s", text);
    sgl_close(out);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
