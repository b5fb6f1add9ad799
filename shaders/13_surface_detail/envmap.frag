#version 430 core
// Lab 13, scene envmap: a sphere of radius u_radius at the origin, seen from
// +z by an orthographic camera, its normal from the sphere's equation; the
// cube map seen in it by reflection, refraction, or both mixed by Fresnel.
#include "shared.glsl"

in vec2 v_uv;  // 0 to 1 across the viewport (screen.vert)

uniform samplerCube u_env;
uniform int u_env_mode;  // ENV_*
uniform float u_ior;
uniform float u_radius;

out vec4 frag_color;

void main() {
    // The world position (x, y) of ortho(-2, 2, -2, 2).
    vec2 xy = (v_uv * 2.0 - 1.0) * 2.0;
    float r2 = dot(xy, xy), rr = u_radius * u_radius;
    if (r2 >= rr) {
        frag_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 n = vec3(xy, sqrt(rr - r2)) / u_radius;
    // The view direction: from the eye, pointing at the surface.
    vec3 incident = vec3(0.0, 0.0, -1.0);
    vec3 reflected = vec3(0.0), refracted = vec3(0.0);
    float fresnel = 0.0;
    // BEGIN SOLUTION
    // STUDENT: // TODO: reflected, refracted: the cube map u_env in the directions reflect()
    // STUDENT: // and refract() give (the ratio n1 / n2, air 1 to u_ior); fresnel: Schlick's F
    // STUDENT: // with F0 = ((n1 - n2) / (n1 + n2))^2 and cos = dot(-incident, n)
    vec3 r = reflect(incident, n);
    vec3 t = refract(incident, n, 1.0 / u_ior);
    reflected = texture(u_env, r).rgb;
    refracted = texture(u_env, t).rgb;
    float f0 = pow((1.0 - u_ior) / (1.0 + u_ior), 2.0);
    float cosine = clamp(dot(-incident, n), 0.0, 1.0);
    fresnel = f0 + (1.0 - f0) * pow(1.0 - cosine, 5.0);
    // END SOLUTION
    // ENV_NORMAL: the cube map itself, each face where the normal points at it.
    vec3 c = u_env_mode == ENV_NORMAL    ? texture(u_env, n).rgb
             : u_env_mode == ENV_REFLECT ? reflected
             : u_env_mode == ENV_REFRACT ? refracted
                                         : mix(refracted, reflected, fresnel);
    frag_color = vec4(c, 1.0);
}
