// The environment seen directly by the camera (behind the spheres).
layout(location = 0) out vec4 out_color;

void main() {
    vec3 d = camera_ray(gl_FragCoord.xy);
#if defined(REFLECTED_EMITTER)
    vec3 emitted;  // an emitter an effect puts in the room (a sphere light), in front of the room
    if (REFLECTED_EMITTER(u_camera_position, d, emitted)) {
        out_color = vec4(emitted, 1.0);
        return;
    }
#endif
    out_color = vec4(environment_trace(u_camera_position, d).rgb, 1.0);
}
