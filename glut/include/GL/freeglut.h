/*
 * GL/freeglut.h: softglut's glut.h plus the freeglut extensions it implements
 * (hand-written, checked by tests/glut_tutorials.rs like glut.h).
 */
#ifndef SOFTGLUT_FREEGLUT_H
#define SOFTGLUT_FREEGLUT_H

#include <GL/glut.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLUT_KEY_NUM_LOCK                    0x006D
#define GLUT_KEY_BEGIN                       0x006E
#define GLUT_KEY_DELETE                      0x006F
#define GLUT_KEY_SHIFT_L                     0x0070
#define GLUT_KEY_SHIFT_R                     0x0071
#define GLUT_KEY_CTRL_L                      0x0072
#define GLUT_KEY_CTRL_R                      0x0073
#define GLUT_KEY_ALT_L                       0x0074
#define GLUT_KEY_ALT_R                       0x0075
#define GLUT_KEY_SUPER_L                     0x0076
#define GLUT_KEY_SUPER_R                     0x0077
#define GLUT_ACTIVE_SUPER                    0x0008
#define GLUT_ACTION_EXIT                     0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS     1
#define GLUT_ACTION_CONTINUE_EXECUTION       2
#define GLUT_CREATE_NEW_CONTEXT              0
#define GLUT_USE_CURRENT_CONTEXT             1
#define GLUT_FORCE_INDIRECT_CONTEXT          0
#define GLUT_ALLOW_DIRECT_CONTEXT            1
#define GLUT_TRY_DIRECT_CONTEXT              2
#define GLUT_FORCE_DIRECT_CONTEXT            3
#define GLUT_INIT_STATE                      0x007C
#define GLUT_ACTION_ON_WINDOW_CLOSE          0x01F9
#define GLUT_WINDOW_BORDER_WIDTH             0x01FA
#define GLUT_WINDOW_BORDER_HEIGHT            0x01FB
#define GLUT_VERSION                         0x01FC
#define GLUT_RENDERING_CONTEXT               0x01FD
#define GLUT_DIRECT_RENDERING                0x01FE
#define GLUT_FULL_SCREEN                     0x01FF
#define GLUT_SKIP_STALE_MOTION_EVENTS        0x0204
#define GLUT_GEOMETRY_VISUALIZE_NORMALS      0x0205
#define GLUT_WINDOW_SRGB                     0x007D
#define GLUT_AUX                             0x1000
#define GLUT_AUX1                            0x1000
#define GLUT_AUX2                            0x2000
#define GLUT_AUX3                            0x4000
#define GLUT_AUX4                            0x8000
#define GLUT_INIT_MAJOR_VERSION              0x0200
#define GLUT_INIT_MINOR_VERSION              0x0201
#define GLUT_INIT_FLAGS                      0x0202
#define GLUT_INIT_PROFILE                    0x0203
#define GLUT_DEBUG                           0x0001
#define GLUT_FORWARD_COMPATIBLE              0x0002
#define GLUT_CORE_PROFILE                    0x0001
#define GLUT_COMPATIBILITY_PROFILE           0x0002
#define GLUT_SPACEBALL_BUTTON_A              0x0001
#define GLUT_SPACEBALL_BUTTON_B              0x0002
#define GLUT_SPACEBALL_BUTTON_C              0x0004
#define GLUT_SPACEBALL_BUTTON_D              0x0008
#define GLUT_SPACEBALL_BUTTON_E              0x0010
#define GLUT_HAS_MULTI                       1
#define GLUT_APPSTATUS_PAUSE                 0x0001
#define GLUT_APPSTATUS_RESUME                0x0002
#define GLUT_CAPTIONLESS                     0x0400
#define GLUT_BORDERLESS                      0x0800
#define GLUT_SRGB                            0x1000

GLUTAPI void glutInitContextVersion(int majorVersion, int minorVersion);
GLUTAPI void glutInitContextFlags(int flags);
GLUTAPI void glutInitContextProfile(int profile);
GLUTAPI void glutSetMenuFont(int menuID, void *font);
GLUTAPI void glutMenuDestroyFunc(void (*callback)(void));
GLUTAPI void *glutGetMenuData(void);
GLUTAPI void glutSetMenuData(void *data);
GLUTAPI void glutMainLoopEvent(void);
GLUTAPI void glutLeaveMainLoop(void);
GLUTAPI void glutSetOption(GLenum option_flag, int value);
GLUTAPI void glutCloseFunc(void (*callback)(void));
GLUTAPI void glutWMCloseFunc(void (*callback)(void));
GLUTAPI int glutBitmapHeight(void *font);
GLUTAPI GLfloat glutStrokeHeight(void *font);
GLUTAPI GLfloat glutStrokeWidthf(void *font, int character);
GLUTAPI void glutBitmapString(void *font, const unsigned char *string);
GLUTAPI void glutStrokeString(void *font, const unsigned char *string);
GLUTAPI void glutWireRhombicDodecahedron(void);
GLUTAPI void glutSolidRhombicDodecahedron(void);
GLUTAPI void glutWireCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks);
GLUTAPI void glutSolidCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks);
GLUTAPI void glutWireSierpinskiSponge(int num_levels, GLdouble offset[3], GLdouble scale);
GLUTAPI void glutSolidSierpinskiSponge(int num_levels, GLdouble offset[3], GLdouble scale);
GLUTAPI void glutWireTeacup(GLdouble size);
GLUTAPI void glutSolidTeacup(GLdouble size);
GLUTAPI void glutWireTeaspoon(GLdouble size);
GLUTAPI void glutSolidTeaspoon(GLdouble size);

#ifdef __cplusplus
}
#endif

#endif /* SOFTGLUT_FREEGLUT_H */
