// rule: 4.10 Order of Qualification / 9 Grammar: a declaration has one layout qualifier, `layout(a, b)`, not `layout(a) layout(b)` (ES 3.10 allows several)
// glslang: accepts: glslang merges several layout qualifiers in every version. rasterd rejects
layout(std140) layout(row_major) uniform Settings { mat2 turn; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(turn[0], turn[1]);
}
