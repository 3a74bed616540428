/*
 * demo.c - render one frame with OSMesa and write it to demo.png.
 *
 * A field of smooth-shaded, depth-tested cubes over a height-field, seen
 * through a glFrustum perspective.  Uses only triangles, colours, depth,
 * culling, matrices and vertex arrays.  The PNG is written by a tiny
 * encoder below (zlib "stored" blocks, CRC-32, Adler-32), so the program
 * needs nothing but OSMesa (or softgl) and libm.
 *
 * Build and run against softgl:
 *   cargo build --release
 *   cc -O2 -Iinclude examples/demo.c -o demo -Ltarget/release -lsoftgl \
 *      -Wl,-rpath,$PWD/target/release -lm
 *   ./demo            # writes demo.png (or ./demo OUT.png)
 * Against Mesa's OSMesa: cc -O2 examples/demo.c -o demo -lOSMesa -lm
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 640
#define HEIGHT 480
#define GRID 64

/* ---- minimal PNG writer ------------------------------------------------ */

static unsigned long crc_table[256];

static void make_crc_table(void)
{
    unsigned long c;
    int n, k;
    for (n = 0; n < 256; n++) {
        c = (unsigned long)n;
        for (k = 0; k < 8; k++)
            c = (c & 1) ? 0xedb88320UL ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

static unsigned long crc_update(unsigned long crc, const unsigned char *p, size_t n)
{
    while (n--)
        crc = crc_table[(crc ^ *p++) & 0xff] ^ (crc >> 8);
    return crc;
}

static void put_u32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void write_chunk(FILE *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char b[4];
    unsigned long crc;
    put_u32(b, (unsigned long)n);
    fwrite(b, 1, 4, f);
    fwrite(type, 1, 4, f);
    fwrite(data, 1, n, f);
    crc = crc_update(0xffffffffUL, (const unsigned char *)type, 4);
    crc = crc_update(crc, data, n) ^ 0xffffffffUL;
    put_u32(b, crc);
    fwrite(b, 1, 4, f);
}

/* Write an RGBA image whose first row in memory is the bottom row. */
static int write_png(const char *path, int w, int h, const unsigned char *rgba)
{
    size_t rowlen = (size_t)w * 4 + 1, rawlen = rowlen * (size_t)h;
    size_t nblocks = (rawlen + 65534) / 65535;
    size_t zlen = 2 + rawlen + 5 * nblocks + 4, i, pos = 0, off = 0;
    unsigned char *raw = malloc(rawlen), *z = malloc(zlen), ihdr[13];
    unsigned long a = 1, b = 0;
    int y;
    FILE *f;
    if (!raw || !z)
        return 0;
    for (y = 0; y < h; y++) { /* filter byte 0, rows flipped to top-down */
        raw[(size_t)y * rowlen] = 0;
        memcpy(raw + (size_t)y * rowlen + 1, rgba + (size_t)(h - 1 - y) * w * 4, (size_t)w * 4);
    }
    z[pos++] = 0x78; /* zlib header: deflate, 32K window, no compression */
    z[pos++] = 0x01;
    while (off < rawlen) {
        size_t n = rawlen - off > 65535 ? 65535 : rawlen - off;
        z[pos++] = off + n == rawlen; /* BFINAL, BTYPE=00 (stored) */
        z[pos++] = (unsigned char)(n & 0xff);
        z[pos++] = (unsigned char)(n >> 8);
        z[pos++] = (unsigned char)(~n & 0xff);
        z[pos++] = (unsigned char)((~n >> 8) & 0xff);
        memcpy(z + pos, raw + off, n);
        pos += n;
        off += n;
    }
    for (i = 0; i < rawlen; i++) { /* Adler-32 */
        a = (a + raw[i]) % 65521;
        b = (b + a) % 65521;
    }
    put_u32(z + pos, (b << 16) | a);
    pos += 4;

    f = fopen(path, "wb");
    if (!f)
        return 0;
    make_crc_table();
    fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
    put_u32(ihdr, (unsigned long)w);
    put_u32(ihdr + 4, (unsigned long)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 6;  /* colour type RGBA */
    ihdr[10] = 0; /* compression */
    ihdr[11] = 0; /* filter */
    ihdr[12] = 0; /* interlace */
    write_chunk(f, "IHDR", ihdr, 13);
    write_chunk(f, "IDAT", z, pos);
    write_chunk(f, "IEND", NULL, 0);
    free(raw);
    free(z);
    return fclose(f) == 0;
}

/* ---- the scene ----------------------------------------------------------- */

static void cube(float r, float g, float b)
{
    static const GLfloat v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const GLubyte faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                        {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    static const GLfloat shade[6] = {0.55f, 1.0f, 0.7f, 0.9f, 0.8f, 0.6f};
    int f, k;
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++)
        for (k = 0; k < 4; k++) {
            const GLfloat *p = v[faces[f][k]];
            float s = shade[f] * (0.8f + 0.2f * p[1]);
            glColor3f(r * s + 0.1f * (p[0] > 0), g * s, b * s + 0.1f * (p[2] > 0));
            glVertex3fv(p);
        }
    glEnd();
}

static float height(float x, float z)
{
    return 0.6f * sinf(0.7f * x) * cosf(0.5f * z) + 0.25f * sinf(1.9f * x + 1.3f * z);
}

static void terrain(void)
{
    static GLfloat pos[GRID * GRID][3], col[GRID * GRID][3];
    static GLuint idx[(GRID - 1) * (GRID - 1) * 6];
    int i, j, n = 0;
    for (j = 0; j < GRID; j++)
        for (i = 0; i < GRID; i++) {
            float x = -12.0f + 24.0f * i / (GRID - 1), z = -12.0f + 24.0f * j / (GRID - 1);
            float y = height(x, z);
            GLfloat *p = pos[j * GRID + i], *c = col[j * GRID + i];
            p[0] = x;
            p[1] = y - 1.6f;
            p[2] = z;
            c[0] = 0.25f + 0.35f * y;
            c[1] = 0.45f + 0.3f * y;
            c[2] = 0.3f - 0.1f * y;
        }
    for (j = 0; j < GRID - 1; j++)
        for (i = 0; i < GRID - 1; i++) {
            GLuint a = j * GRID + i, b = a + 1, c = a + GRID, d = c + 1;
            idx[n++] = a; idx[n++] = c; idx[n++] = b;
            idx[n++] = b; idx[n++] = c; idx[n++] = d;
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_FLOAT, 0, col);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, idx);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "demo.png";
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf = malloc((size_t)WIDTH * HEIGHT * 4);
    int i;
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
        fprintf(stderr, "demo: could not create an OSMesa context\n");
        return 1;
    }

    glClearColor(0.55f, 0.68f, 0.86f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);

    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, -0.8f, -11.0f);
    glRotatef(24.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-18.0f, 0.0f, 1.0f, 0.0f);

    terrain();

    for (i = 0; i < 12; i++) {
        float a = i * 0.5235988f, r = 3.2f + 1.4f * (i & 1);
        float x = r * cosf(a), z = r * sinf(a);
        glPushMatrix();
        glTranslatef(x, height(x, z) - 0.6f + 0.25f * (i % 3), z);
        glRotatef(37.0f * i, 0.3f, 1.0f, 0.2f);
        glScalef(0.55f, 0.55f, 0.55f);
        cube(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * cosf(a + 2.094f), 0.5f + 0.5f * cosf(a + 4.189f));
        glPopMatrix();
    }
    glPushMatrix(); /* a big cube in the middle */
    glTranslatef(0.0f, 0.6f, 0.0f);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    glScalef(1.1f, 1.1f, 1.1f);
    cube(1.0f, 0.85f, 0.35f);
    glPopMatrix();

    glFinish();
    if (!write_png(path, WIDTH, HEIGHT, buf)) {
        fprintf(stderr, "demo: could not write %s\n", path);
        return 1;
    }
    printf("wrote %s (%dx%d)\n", path, WIDTH, HEIGHT);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
