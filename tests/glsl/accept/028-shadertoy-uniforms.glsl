// exercises: every uniform of the prelude (iResolution, iTime, iTimeDelta, iFrameRate, iFrame, iChannelTime, iChannelResolution, iMouse, iDate, iSampleRate, iChannel0..3) read in ordinary ways
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float aspect = iResolution.x / iResolution.y * iResolution.z;
    vec2 mouse = iMouse.xy / iResolution.xy;
    bool pressed = iMouse.z > 0.0;
    float seconds = iDate.w + iDate.x * 0.0 + iDate.y * 0.0 + iDate.z * 0.0;
    float t = iTime + iTimeDelta * iFrameRate + float(iFrame) * 0.0 + iSampleRate * 0.0;
    vec3 col = texture(iChannel0, uv).rgb + texture(iChannel1, uv).rgb
             + texture(iChannel2, uv * iChannelResolution[2].xy / iResolution.xy).rgb
             + texture(iChannel3, uv).rgb * iChannelTime[3];
    col *= 0.5 + 0.5 * cos(t + uv.xyx + vec3(0.0, 2.0, 4.0)) * aspect;
    fragColor = vec4(col * (pressed ? distance(uv, mouse) : 1.0), fract(seconds));
}
