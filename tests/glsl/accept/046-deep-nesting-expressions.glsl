// exercises: deeply nested parentheses, ?: chains, calls as arguments of calls, long operator chains mixing precedence levels, unary operator sequences
float f(float x) { return x * 0.5; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    float a = ((((((p.x + 1.0) * 2.0) - 3.0) / 4.0) + 5.0) * ((p.y)));
    float b = f(f(f(f(f(f(a))))));
    float c = p.x < 0.1 ? 0.1 : p.x < 0.2 ? 0.2 : p.x < 0.3 ? 0.3 : p.x < 0.4 ? 0.4 : 0.5;
    float d = 1.0 + 2.0 * 3.0 - 4.0 / 5.0 * -6.0 + - - 7.0 - +8.0;
    int e = 1 + 2 * 3 % 4 << 1 >> 1 & 7 ^ 3 | 8;
    bool g = !!(p.x > 0.5) == !(p.y <= 0.5) && (a < b || c > d) ^^ e == 3;
    fragColor = vec4(a, b, c + d * 0.01, g ? float(e) : -float(~e));
}
