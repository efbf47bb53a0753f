/*
 * GL errors as a program sees them (glGetError after each invalid call:
 * GL 1.5 spec 2.5, 2.6.3, 2.11.2, 3.4, 5.4), written for OSMesa.
 * tests/cli_shim.sh runs it on OSMesa and on fragsim's shim and expects the
 * same output, and checks the shim's FRAGSIM_STATS "errors" list: each error
 * with the number of the program's GL call that raised it (counted from 0),
 * its command and its name.  The comments number the GL calls.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

int main(void)
{
    static unsigned char buf[16 * 16 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 16, 16))
        return 1;
    glClearColor(0, 0, 0, 1);                               /* 0 */
    glEnable(0x1234);                                       /* 1: GL_INVALID_ENUM */
    printf("glEnable(0x1234): 0x%04x\n", glGetError());     /* 2 */
    glNewList(1, GL_COMPILE);                               /* 3 */
    glLineWidth(-1.0f);                                     /* 4: compiled, no error yet */
    glEndList();                                            /* 5 */
    printf("compiling: 0x%04x\n", glGetError());            /* 6 */
    glCallList(1);                                          /* 7: GL_INVALID_VALUE */
    printf("glCallList: 0x%04x\n", glGetError());           /* 8 */
    glPopMatrix();                                          /* 9: GL_STACK_UNDERFLOW */
    printf("glPopMatrix: 0x%04x\n", glGetError());          /* 10 */
    glBegin(GL_TRIANGLES);                                  /* 11 */
    glEnable(GL_DEPTH_TEST);                                /* 12: GL_INVALID_OPERATION */
    glEnd();                                                /* 13 */
    printf("glEnable in glBegin: 0x%04x\n", glGetError());  /* 14 */
    glFinish();                                             /* 15 */
    OSMesaDestroyContext(c);
    return 0;
}
