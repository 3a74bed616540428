#version 330
out vec4 o;
uniform int n;
uniform float k[4];

struct Ray { vec3 o, d; };
struct Hit { float t; int id; Ray r; };

bool hitSphere(in Ray r, vec3 c, float rad, out Hit h)
{
    vec3 oc = r.o - c;
    float b = dot(oc, r.d), cc = dot(oc, oc) - rad * rad;
    float disc = b * b - cc;
    if (disc < 0.0) return false;
    h.t = -b - sqrt(disc);
    h.id = 1;
    h.r = r;
    return h.t > 0.0;
}

void main()
{
    Ray r = Ray(vec3(0.0), normalize(vec3(gl_FragCoord.xy, 1.0)));
    Hit h;
    int i = 0, j;
    float acc = 0.0;
    for (;;) { if (++i > 3) break; }
    for (int q = 0, w = 1; q < n; q += w) { acc += k[q & 3]; continue; }
    while (i-- > 0) acc *= 0.5;
    while (bool go = acc > 1.0) { acc -= 1.0; }
    do { j = i++; } while (j < 10);
    acc = i > 2 ? acc : -acc, acc += 1.0;
    acc = (acc, 2.0);
    {
        float inner = acc;
        { inner *= 2.0; }
        acc = inner;
    }
    ;
    if (hitSphere(r, vec3(0.0, 0.0, 5.0), 1.0, h)) o = vec4(h.t);
    else if (h.id == 2) o = vec4(0.5);
    else o = vec4(acc);
    o.xy = o.yx;
    o.zw += vec2(-1.0, +1.0);
    vec4 arr[2];
    arr[0] = o;
    arr[1] = -arr[0];
    o = arr[arr.length() - 1];
    mat2 m = mat2(1.0);
    m[0][1] = 2.0;
    o.x += m[0].y + float(!true) + float(~3) + float(-(-(1)));
    o.y -= float(h.id--) - float(--h.id) + float(h.id++);
    i <<= 1; i >>= 1; i &= 7; i |= 1; i ^= 2; i %= 5; i /= 2; i *= 3;
    acc = float(i) * (1.0e2 + 2.5E-3 + .5 + 1. + 3e1 + 4.0f);
}
