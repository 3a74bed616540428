/*
 * GLUT state a program can see without events: menu ids, the current menu, item
 * counts after adding, changing and removing items, destroy callbacks, menu data,
 * the freeglut context requests and options. tests/glut_tutorials.rs runs it with
 * softglut (on Mesa's OSMesa) and with the system freeglut (under Xvfb) and compares
 * the output.
 */
#include <GL/freeglut.h>
#include <stdio.h>

static void pick(int value)
{
    (void)value;
}

static void destroyed(void)
{
    printf("destroy callback: current menu %d\n", glutGetMenu());
}

static void show(const char *what)
{
    printf("%-28s menu %d items %d\n", what, glutGetMenu(), glutGet(GLUT_MENU_NUM_ITEMS));
}

int main(int argc, char **argv)
{
    int a, b, c, d, win, data = 42;

    glutInit(&argc, argv);
    printf("init context %d.%d flags %d profile %d\n", glutGet(GLUT_INIT_MAJOR_VERSION),
           glutGet(GLUT_INIT_MINOR_VERSION), glutGet(GLUT_INIT_FLAGS), glutGet(GLUT_INIT_PROFILE));
    glutInitContextVersion(2, 1);
    glutInitContextFlags(GLUT_DEBUG);
    glutInitContextProfile(GLUT_COMPATIBILITY_PROFILE);
    printf("init context %d.%d flags %d profile %d\n", glutGet(GLUT_INIT_MAJOR_VERSION),
           glutGet(GLUT_INIT_MINOR_VERSION), glutGet(GLUT_INIT_FLAGS), glutGet(GLUT_INIT_PROFILE));
    printf("samples option %d\n", glutGet(GLUT_MULTISAMPLE));
    glutSetOption(GLUT_MULTISAMPLE, 8);
    printf("samples option %d\n", glutGet(GLUT_MULTISAMPLE));
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_ACCUM);
    printf("display mode %#x\n", glutGet(GLUT_INIT_DISPLAY_MODE));
    win = glutCreateWindow("menus");
    printf("window %d, accumulation buffer: %s\n", win,
           glutGet(GLUT_WINDOW_ACCUM_RED_SIZE) > 0 ? "yes" : "no");

    show("before any menu");
    a = glutCreateMenu(pick);
    show("created a");
    glutAddMenuEntry("one", 1);
    glutAddMenuEntry("two", 2);
    glutAddMenuEntry("three", 3);
    show("three entries");
    b = glutCreateMenu(pick);
    glutMenuDestroyFunc(destroyed);
    glutSetMenuData(&data);
    glutAddSubMenu("to a", a);
    glutAddSubMenu("to nowhere", 99);
    show("created b");
    glutAttachMenu(GLUT_RIGHT_BUTTON);
    glutSetMenu(a);
    show("set a");
    printf("menu data of a is %s\n", glutGetMenuData() == &data ? "b's" : "not b's");
    glutSetMenu(77);
    show("set 77 (no such menu)");
    glutChangeToMenuEntry(2, "deux", 22);
    glutChangeToSubMenu(3, "to b", b);
    glutChangeToMenuEntry(9, "nine", 9);
    glutRemoveMenuItem(1);
    glutRemoveMenuItem(0);
    glutRemoveMenuItem(7);
    show("changed and removed in a");
    glutSetMenu(b);
    printf("menu data of b is %s\n", glutGetMenuData() == &data ? "b's" : "not b's");
    glutSetMenu(a);
    glutDestroyMenu(b);
    show("destroyed b (a current)");
    c = glutCreateMenu(NULL);
    show("created c");
    glutDestroyMenu(c);
    show("destroyed c (current)");
    glutDestroyMenu(c);
    d = glutCreateMenu(pick);
    printf("ids a %d b %d c %d d %d\n", a, b, c, d);
    glutDetachMenu(GLUT_RIGHT_BUTTON);
    glutAttachMenu(GLUT_LEFT_BUTTON);
    glutDestroyWindow(win);
    show("window gone");
    return 0;
}
