#version 430 core
// Lab 3: each square in its flat colour (show=color), or its linearised
// depth as grey (show=depth): black at the near plane, white at the far one.

uniform vec3 u_color;
uniform bool u_show_depth;
uniform bool u_orthographic;
uniform float u_near;
uniform float u_far;

layout(location = 0) out vec4 frag_color;

// The distance z = -z_eye in front of the eye of a fragment at window depth
// d (gl_FragCoord.z, the value the depth test compares). Perspective:
// d = f (1 - n / z) / (f - n), solved for z. Orthographic: d is linear in z.
float eye_distance(float d) {
    if (u_orthographic) return u_near + d * (u_far - u_near);
    return u_near * u_far / (u_far - d * (u_far - u_near));
}

void main() {
    if (u_show_depth) {
        float grey = (eye_distance(gl_FragCoord.z) - u_near) / (u_far - u_near);
        frag_color = vec4(vec3(grey), 1.0);
    } else {
        frag_color = vec4(u_color, 1.0);
    }
}
