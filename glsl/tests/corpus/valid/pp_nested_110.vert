#define A 1
#if A
# if defined(B)
#  error B is not defined
# elif A == 1
#  define C 3
# else
#  error no
# endif
#endif
#ifdef NOT_DEFINED
  this is not GLSL at all @ $ "
# bogus directive in skipped group
#endif
#if 0
#else
uniform float u[C];
#endif
#define F(x, y) x##y
#define G() 5
void main()
{
    gl_Position = vec4(u[0], u[1], u[2], float(G()));
}
