// exercises: 3.6/3.7 names that are not reserved in ES 3.00 (buffer, packed, precise, shared... see glslang-differs for shared), identifiers with a GL_ prefix (reserved only for macros), very long identifiers, identifiers containing keywords
float buffer = 1.0;
float packed(float precise) { return precise * 2.0; }
struct Like { float v; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float GL_value = 0.5;
    float classy = 1.0, go_to = 2.0, floatx = 3.0, int_ = 4.0, in_ = 5.0, outer = 6.0, uniformity = 7.0, sampler2Dish = 8.0;
    float a_very_long_identifier_name_that_goes_on_and_on_and_on_for_quite_a_while_to_test_identifier_length_limits_0123456789 = 9.0;
    Like l = Like(1.0);
    fragColor = vec4(packed(buffer) + GL_value + l.v, classy + go_to + floatx + int_ + in_ + outer + uniformity + sampler2Dish,
                     a_very_long_identifier_name_that_goes_on_and_on_and_on_for_quite_a_while_to_test_identifier_length_limits_0123456789, 1.0) * 0.01;
}
