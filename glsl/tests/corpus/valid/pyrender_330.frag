#version 330 core
///////////////////////////////////////////////////////////////////////////////
// Structs
///////////////////////////////////////////////////////////////////////////////
struct SpotLight {
    vec3 color;
    float intensity;
    float range;
    vec3 position;
    vec3 direction;
    float light_angle_scale;
    float light_angle_offset;
    #ifdef SPOT_LIGHT_SHADOWS
    sampler2D shadow_map;
    mat4 light_matrix;
    #endif
};
struct Material {
    vec3 emissive_factor;
#ifdef USE_METALLIC_MATERIAL
    vec4 base_color_factor;
    float metallic_factor;
    float roughness_factor;
#endif
    float alpha_cutoff;
};
#define MAX_SPOT_LIGHTS 8
uniform SpotLight spot_lights[MAX_SPOT_LIGHTS];
uniform int n_spot_lights;
uniform vec3 cam_pos;
uniform Material material;
in vec3 frag_position;
#ifdef NORMAL_LOC
in vec3 frag_normal;
#endif
out vec4 frag_color;
const float PI = 3.141592653589793;
const float min_roughness = 0.04;

float get_spot_attenuation(vec3 point_to_light, vec3 spot_direction,
                           float light_angle_scale, float light_angle_offset)
{
    float cd = dot(spot_direction, point_to_light);
    float attenuation = clamp(cd * light_angle_scale + light_angle_offset, 0.0, 1.0);
    attenuation *= attenuation;
    return attenuation;
}

void main()
{
    vec4 color = vec4(vec3(0.0), 1.0);
    vec3 v = normalize(cam_pos - frag_position);
    for (int i = 0; i < n_spot_lights; i++) {
        vec3 position = spot_lights[i].position;
        vec3 l = normalize(position - frag_position);
        float dist = length(position - frag_position);
        float attenuation = 1.0 / (dist * dist);
        attenuation *= get_spot_attenuation(-l, spot_lights[i].direction,
            spot_lights[i].light_angle_scale, spot_lights[i].light_angle_offset);
        color.xyz += attenuation * spot_lights[i].color * spot_lights[i].intensity;
    }
    color.xyz += material.emissive_factor;
    frag_color = clamp(vec4(pow(color.xyz, vec3(1.0/2.2)), color.a), 0.0, 1.0);
}
