/* A program that defines a gl* function of its own (a glFinish wrapper): the GL
 * library must keep using, and handing out through OSMesaGetProcAddress, its own
 * glFinish, as Mesa's libOSMesa (linked -Bsymbolic) does. Prints what it saw. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
static int calls;
/* The program's own glFinish, as a wrapper would be. */
void GLAPIENTRY glFinish(void) { calls++; }
int main(void)
{
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf = calloc(16 * 16, 4);
    OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16);
    void (*p)(void) = (void (*)(void))OSMesaGetProcAddress("glFinish");
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (p) p();
    printf("proc_is_program_s %d program_calls %d pixel %d\n", p == glFinish, calls, buf[0]);
    return 0;
}
