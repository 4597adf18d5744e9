// rule: 6.2 Selection: no statement (a declaration is a statement) may come before the first case label
// glslang: accepts: glslang rejects other statements there (reject/*-switch-statement-before-case) and a declaration with an initialiser, but not a plain declaration. rasterd rejects
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        float unused;
        case 1: fragColor = vec4(1.0); break;
    }
}
