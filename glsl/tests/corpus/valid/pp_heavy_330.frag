#version 330 core
// Preprocessor workout: function-like macros, nesting, conditionals, line control.
#define PI 3.14159265
#define TWO_PI (2.0 * PI)
#define SQR(x) ((x) * (x))
#define MAD(a, b, c) ((a) * (b) + (c))
#define EMPTY()
#define CALL(f, x) f(x)
#define SELF SELF
#define REC(x) REC(x + 1)
#define NUM_LIGHTS 3
#define USE_FOG
#undef USE_FOG
#define MULTI_LINE(a, b) \
    ((a) + \
     (b))

#if NUM_LIGHTS > 2 && defined(PI) && !defined USE_FOG
#  define QUALITY 2
#elif NUM_LIGHTS > 1
#  define QUALITY 1
#else
#  define QUALITY 0
#endif

#ifndef QUALITY
#error QUALITY must be defined
#endif

#if (QUALITY << 2) != 8 || (0x1F & 7) != 7 || (-3 / 2) != -1 || (7 % 3) != 1
#error arithmetic
#endif

#if __VERSION__ >= 330 && GL_core_profile
const int version = __VERSION__;
#endif

#pragma optimize(on)
#pragma debug(off)

out vec4 color;
uniform vec3 c[NUM_LIGHTS];

float f(float x) { return x; }

void main()
{
    float SELF = 1.0;
    float a = SQR(TWO_PI) + MAD(1.0, 2.0, 3.0) + CALL(f, SQR(2.0)) EMPTY();
    float REC = 2.0;
    float b = MULTI_LINE(a, SELF) + REC;
    int line = __LINE__;
#line 100
    int l100 = __LINE__ + __FILE__;
    color = vec4(c[QUALITY - 1], a + b + float(line + l100 + version));
}
