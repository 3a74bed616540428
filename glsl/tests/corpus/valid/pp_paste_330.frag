#version 330
#define CAT(a,b) a ## b
#define V vec
CAT(V,4) p; CAT(vec, 3) q;
void main(){ CAT(p,) = vec4(q, 1.0); }
