// exercises: 7.2 fragment built-in variables gl_FragCoord, gl_FrontFacing, gl_PointCoord (read) and gl_FragDepth (write), 7.4 gl_DepthRange, 7.3 every ES 3.00 built-in constant
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 fc = gl_FragCoord;
    float facing = gl_FrontFacing ? 1.0 : -1.0;
    vec2 pc = gl_PointCoord;
    float range = gl_DepthRange.near + gl_DepthRange.far + gl_DepthRange.diff;
    int consts = gl_MaxVertexAttribs + gl_MaxVertexUniformVectors + gl_MaxVertexOutputVectors
               + gl_MaxFragmentInputVectors + gl_MaxVertexTextureImageUnits + gl_MaxCombinedTextureImageUnits
               + gl_MaxTextureImageUnits + gl_MaxFragmentUniformVectors + gl_MaxDrawBuffers
               + gl_MinProgramTexelOffset + gl_MaxProgramTexelOffset;
    float arr[gl_MaxDrawBuffers];
    arr[0] = 1.0;
    gl_FragDepth = fc.z;
    fragColor = vec4(fc.xy / iResolution.xy * facing, pc.x + range, float(consts) * 0.0 + arr[0]);
}
