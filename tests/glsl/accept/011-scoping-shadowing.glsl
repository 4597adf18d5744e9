// exercises: 4.2 scoping: nested blocks shadowing locals, globals, parameters and functions; loop variables reused in sibling loops; a struct name shadowed in an inner scope
float value = 1.0;
float level(float x) { return x * 2.0; }
struct S { float a; };
float f(float x) {
    float r = x;
    {
        float x = 3.0;
        r += x;
    }
    return r;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float value = 2.0;
    float total = value + level(1.0);
    {
        float value = 3.0;
        total += value;
        {
            int value = 4;
            total += float(value);
        }
    }
    for (int i = 0; i < 2; i++) total += float(i);
    for (int i = 0; i < 3; i++) { float total2 = total; total = total2 + 1.0; }
    {
        float level = 5.0;
        total += level;
    }
    {
        struct S { int b; };
        S s = S(2);
        total += float(s.b);
    }
    S outer = S(1.0);
    total += outer.a + f(1.0);
    fragColor = vec4(fract(total * 0.1));
}
