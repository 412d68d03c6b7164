// The environment seen directly by the camera (behind the spheres).
layout(location = 0) out vec4 out_color;

void main() {
    vec3 d = camera_ray(gl_FragCoord.xy);
    out_color = vec4(environment_trace(u_camera_position, d).rgb, 1.0);
}
