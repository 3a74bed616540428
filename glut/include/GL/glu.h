/*
 * GL/glu.h: the part of GLU 1.3 that softglut implements (libsoftglut.so), with the
 * standard names, signatures and values. Hand-written; tests/glut_tutorials.rs checks
 * it against libsoftglut.so's exports and the values against the system's glu.h.
 * Tessellators and NURBS are not provided.
 */
#ifndef SOFTGLUT_GLU_H
#define SOFTGLUT_GLU_H
/* The system glu.h's guard, so that both are never seen together. */
#ifndef __glu_h__
#define __glu_h__

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifndef GLUAPI
#define GLUAPI extern
#endif

#define GLU_VERSION_1_1                      1
#define GLU_VERSION_1_2                      1
#define GLU_VERSION_1_3                      1
#define GLU_FALSE                            0
#define GLU_TRUE                             1

#define GLU_VERSION                          100800
#define GLU_EXTENSIONS                       100801

#define GLU_INVALID_ENUM                     100900
#define GLU_INVALID_VALUE                    100901
#define GLU_OUT_OF_MEMORY                    100902
#define GLU_INCOMPATIBLE_GL_VERSION          100903
#define GLU_INVALID_OPERATION                100904

#define GLU_SMOOTH                           100000
#define GLU_FLAT                             100001
#define GLU_NONE                             100002
#define GLU_POINT                            100010
#define GLU_LINE                             100011
#define GLU_FILL                             100012
#define GLU_SILHOUETTE                       100013
#define GLU_OUTSIDE                          100020
#define GLU_INSIDE                           100021
#define GLU_ERROR                            100103

typedef struct GLUquadric GLUquadric;
typedef GLUquadric GLUquadricObj;

GLUAPI void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar);
GLUAPI void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
GLUAPI void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY, GLdouble centerZ, GLdouble upX, GLdouble upY, GLdouble upZ);
GLUAPI void gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint *viewport);
GLUAPI GLint gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble *model, const GLdouble *proj, const GLint *view, GLdouble *winX, GLdouble *winY, GLdouble *winZ);
GLUAPI GLint gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble *model, const GLdouble *proj, const GLint *view, GLdouble *objX, GLdouble *objY, GLdouble *objZ);

GLUAPI const GLubyte *gluErrorString(GLenum error);
GLUAPI const GLubyte *gluGetString(GLenum name);

GLUAPI GLUquadric *gluNewQuadric(void);
GLUAPI void gluDeleteQuadric(GLUquadric *quad);
GLUAPI void gluQuadricNormals(GLUquadric *quad, GLenum normal);
GLUAPI void gluQuadricTexture(GLUquadric *quad, GLboolean texture);
GLUAPI void gluQuadricOrientation(GLUquadric *quad, GLenum orientation);
GLUAPI void gluQuadricDrawStyle(GLUquadric *quad, GLenum draw);
GLUAPI void gluQuadricCallback(GLUquadric *quad, GLenum which, void (*CallBackFunc)(void));
GLUAPI void gluSphere(GLUquadric *quad, GLdouble radius, GLint slices, GLint stacks);
GLUAPI void gluCylinder(GLUquadric *quad, GLdouble base, GLdouble top, GLdouble height, GLint slices, GLint stacks);
GLUAPI void gluDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops);
GLUAPI void gluPartialDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops, GLdouble start, GLdouble sweep);

GLUAPI GLint gluScaleImage(GLenum format, GLsizei wIn, GLsizei hIn, GLenum typeIn, const void *dataIn, GLsizei wOut, GLsizei hOut, GLenum typeOut, GLvoid *dataOut);
GLUAPI GLint gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format, GLenum type, const void *data);
GLUAPI GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *data);

#ifdef __cplusplus
}
#endif

#endif /* __glu_h__ */
#endif /* SOFTGLUT_GLU_H */
