// exercises: 6.3 for, while and do-while loops; nested loops with break and continue; for with empty init, condition and expression; declarations in for and while conditions; float and uint loop counters; loop bodies that are single statements
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; ++j) {
            if (j == 2) continue;
            if (i == 3) break;
            s += 1.0;
        }
    }
    int n = 0;
    for (;;) {
        if (++n > 5) break;
    }
    int m = 0;
    for (; m < 3;) m++;
    for (float x = 0.0; x < 1.0; x += 0.25) s += x;
    for (uint u = 0u; u < 3u; u++) s += float(u);
    int k = 0;
    while (k < 3) k++;
    while (bool more = k < 6) { k++; }
    for (int i = 0; bool go = i < 2; i++) s += 0.5;
    int d = 0;
    do {
        d += 2;
        if (d == 4) continue;
    } while (d < 10);
    do s += 1.0; while (false);
    fragColor = vec4(fract(s * 0.1), float(n + m + k + d) * 0.01, 0.0, 1.0);
}
