// rule: 3.3 Preprocessor: #extension (also `all : warn`) must come before any non-preprocessor token; the prelude's declarations precede the program
// glslang: accepts: glslang does not check the position; ANGLE rejects it in ESSL 3. rasterd rejects
#extension all : warn
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
