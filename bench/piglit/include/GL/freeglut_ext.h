/*
 * GL/freeglut_ext.h for piglit's GLUT build over softglut (bench/piglit/run.sh).
 *
 * piglit includes <GL/freeglut_ext.h> when glut.h defines FREEGLUT, as softglut's does;
 * without this file the compiler would take the system freeglut's. softglut's
 * freeglut.h already declares the extensions it implements. It does not implement
 * glutInitContextVersion/Profile/Flags (every window is a compatibility context), so
 * GLUT_CORE_PROFILE is withdrawn: piglit then skips those calls and runs only tests
 * that accept a compatibility context, which all GL 1.x tests do.
 */
#ifndef SOFTGLUT_PIGLIT_FREEGLUT_EXT_H
#define SOFTGLUT_PIGLIT_FREEGLUT_EXT_H
#include <GL/freeglut.h>
#undef GLUT_CORE_PROFILE
#endif
