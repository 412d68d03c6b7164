// The camera ray through a pixel centre (gl_FragCoord), as camera_ray() in src/camera.cpp.
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;
uniform vec3 u_camera_right;  // scaled by tan(fov/2) · aspect
uniform vec3 u_camera_up;     // scaled by tan(fov/2)
uniform vec2 u_viewport;

vec3 camera_ray(vec2 frag) {
    vec2 ndc = 2.0 * frag / u_viewport - 1.0;
    return normalize(u_camera_forward + ndc.x * u_camera_right + ndc.y * u_camera_up);
}
