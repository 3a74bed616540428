/*
 * glXGetProcAddressARB for piglit's GLUT build, answered by OSMesa.
 *
 * On Linux, piglit's GL dispatch (tests/util/piglit-dispatch-init.c) looks every GL
 * function up with glXGetProcAddressARB when it is built with GLX. run.sh builds piglit
 * with this small library as its "OpenGL library" instead of libGL: it forwards each
 * lookup to OSMesaGetProcAddress of whichever libOSMesa.so.8 the loader found first,
 * so LD_LIBRARY_PATH alone picks softgl's drop-in or Mesa's llvmpipe, and no libGL
 * (whose gl* symbols would shadow OSMesa's for softglut) is loaded.
 */
#include <GL/osmesa.h>

typedef void (*glx_proc)(void);

glx_proc glXGetProcAddressARB(const unsigned char *name);
glx_proc glXGetProcAddress(const unsigned char *name);

/* The ARB name piglit calls. */
glx_proc glXGetProcAddressARB(const unsigned char *name)
{
	return (glx_proc)OSMesaGetProcAddress((const char *)name);
}

/* The GLX 1.4 name, for completeness. */
glx_proc glXGetProcAddress(const unsigned char *name)
{
	return glXGetProcAddressARB(name);
}
