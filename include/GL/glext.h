/*
 * GL/glext.h — OpenGL 1.4/1.5 and extensions
 *
 * softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API.
 *
 * GENERATED FILE, DO NOT EDIT. Produced by cbindgen from the files in src/ffi with
 *   cargo run --example gen_headers
 * (tests/headers.rs fails when this file is stale).
 */

#ifndef __gl_glext_h_
#define __gl_glext_h_ 1
/* The include guard of older Mesa glext.h versions. */
#define __glext_h_ 1

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif
#ifndef GLAPI
#define GLAPI extern
#endif

/* Types: src/ffi/types.rs */
typedef char GLchar;
typedef ptrdiff_t GLsizeiptr;
typedef ptrdiff_t GLintptr;

/* Tokens: src/ffi/glext_enums.rs */
#ifndef GL_VERSION_1_4
#define GL_VERSION_1_4                           1
#define GL_BLEND_DST_RGB                         0x80C8
#define GL_BLEND_SRC_RGB                         0x80C9
#define GL_BLEND_DST_ALPHA                       0x80CA
#define GL_BLEND_SRC_ALPHA                       0x80CB
#define GL_POINT_FADE_THRESHOLD_SIZE             0x8128
#define GL_DEPTH_COMPONENT16                     0x81A5
#define GL_DEPTH_COMPONENT24                     0x81A6
#define GL_DEPTH_COMPONENT32                     0x81A7
#define GL_MIRRORED_REPEAT                       0x8370
#define GL_MAX_TEXTURE_LOD_BIAS                  0x84FD
#define GL_TEXTURE_LOD_BIAS                      0x8501
#define GL_INCR_WRAP                             0x8507
#define GL_DECR_WRAP                             0x8508
#define GL_TEXTURE_DEPTH_SIZE                    0x884A
#define GL_TEXTURE_COMPARE_MODE                  0x884C
#define GL_TEXTURE_COMPARE_FUNC                  0x884D
#define GL_POINT_SIZE_MIN                        0x8126
#define GL_POINT_SIZE_MAX                        0x8127
#define GL_POINT_DISTANCE_ATTENUATION            0x8129
#define GL_GENERATE_MIPMAP                       0x8191
#define GL_GENERATE_MIPMAP_HINT                  0x8192
#define GL_FOG_COORDINATE_SOURCE                 0x8450
#define GL_FOG_COORDINATE                        0x8451
#define GL_FRAGMENT_DEPTH                        0x8452
#define GL_CURRENT_FOG_COORDINATE                0x8453
#define GL_FOG_COORDINATE_ARRAY_TYPE             0x8454
#define GL_FOG_COORDINATE_ARRAY_STRIDE           0x8455
#define GL_FOG_COORDINATE_ARRAY_POINTER          0x8456
#define GL_FOG_COORDINATE_ARRAY                  0x8457
#define GL_COLOR_SUM                             0x8458
#define GL_CURRENT_SECONDARY_COLOR               0x8459
#define GL_SECONDARY_COLOR_ARRAY_SIZE            0x845A
#define GL_SECONDARY_COLOR_ARRAY_TYPE            0x845B
#define GL_SECONDARY_COLOR_ARRAY_STRIDE          0x845C
#define GL_SECONDARY_COLOR_ARRAY_POINTER         0x845D
#define GL_SECONDARY_COLOR_ARRAY                 0x845E
#define GL_TEXTURE_FILTER_CONTROL                0x8500
#define GL_DEPTH_TEXTURE_MODE                    0x884B
#define GL_COMPARE_R_TO_TEXTURE                  0x884E
#endif /* GL_VERSION_1_4 */

#ifndef GL_VERSION_1_5
#define GL_VERSION_1_5                           1
#define GL_BUFFER_SIZE                           0x8764
#define GL_BUFFER_USAGE                          0x8765
#define GL_QUERY_COUNTER_BITS                    0x8864
#define GL_CURRENT_QUERY                         0x8865
#define GL_QUERY_RESULT                          0x8866
#define GL_QUERY_RESULT_AVAILABLE                0x8867
#define GL_ARRAY_BUFFER                          0x8892
#define GL_ELEMENT_ARRAY_BUFFER                  0x8893
#define GL_ARRAY_BUFFER_BINDING                  0x8894
#define GL_ELEMENT_ARRAY_BUFFER_BINDING          0x8895
#define GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING    0x889F
#define GL_READ_ONLY                             0x88B8
#define GL_WRITE_ONLY                            0x88B9
#define GL_READ_WRITE                            0x88BA
#define GL_BUFFER_ACCESS                         0x88BB
#define GL_BUFFER_MAPPED                         0x88BC
#define GL_BUFFER_MAP_POINTER                    0x88BD
#define GL_STREAM_DRAW                           0x88E0
#define GL_STREAM_READ                           0x88E1
#define GL_STREAM_COPY                           0x88E2
#define GL_STATIC_DRAW                           0x88E4
#define GL_STATIC_READ                           0x88E5
#define GL_STATIC_COPY                           0x88E6
#define GL_DYNAMIC_DRAW                          0x88E8
#define GL_DYNAMIC_READ                          0x88E9
#define GL_DYNAMIC_COPY                          0x88EA
#define GL_SAMPLES_PASSED                        0x8914
#define GL_SRC1_ALPHA                            0x8589
#define GL_VERTEX_ARRAY_BUFFER_BINDING           0x8896
#define GL_NORMAL_ARRAY_BUFFER_BINDING           0x8897
#define GL_COLOR_ARRAY_BUFFER_BINDING            0x8898
#define GL_INDEX_ARRAY_BUFFER_BINDING            0x8899
#define GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING    0x889A
#define GL_EDGE_FLAG_ARRAY_BUFFER_BINDING        0x889B
#define GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING  0x889C
#define GL_FOG_COORDINATE_ARRAY_BUFFER_BINDING   0x889D
#define GL_WEIGHT_ARRAY_BUFFER_BINDING           0x889E
#define GL_FOG_COORD_SRC                         0x8450
#define GL_FOG_COORD                             0x8451
#define GL_CURRENT_FOG_COORD                     0x8453
#define GL_FOG_COORD_ARRAY_TYPE                  0x8454
#define GL_FOG_COORD_ARRAY_STRIDE                0x8455
#define GL_FOG_COORD_ARRAY_POINTER               0x8456
#define GL_FOG_COORD_ARRAY                       0x8457
#define GL_FOG_COORD_ARRAY_BUFFER_BINDING        0x889D
#define GL_SRC0_RGB                              0x8580
#define GL_SRC1_RGB                              0x8581
#define GL_SRC2_RGB                              0x8582
#define GL_SRC0_ALPHA                            0x8588
#define GL_SRC2_ALPHA                            0x858A
#endif /* GL_VERSION_1_5 */

#ifndef GL_ARB_clip_control
#define GL_ARB_clip_control                      1
#define GL_LOWER_LEFT                            0x8CA1
#define GL_UPPER_LEFT                            0x8CA2
#define GL_NEGATIVE_ONE_TO_ONE                   0x935E
#define GL_ZERO_TO_ONE                           0x935F
#define GL_CLIP_ORIGIN                           0x935C
#define GL_CLIP_DEPTH_MODE                       0x935D
#endif /* GL_ARB_clip_control */

#ifndef GL_ARB_depth_texture
#define GL_ARB_depth_texture                     1
#define GL_DEPTH_COMPONENT16_ARB                 0x81A5
#define GL_DEPTH_COMPONENT24_ARB                 0x81A6
#define GL_DEPTH_COMPONENT32_ARB                 0x81A7
#define GL_TEXTURE_DEPTH_SIZE_ARB                0x884A
#define GL_DEPTH_TEXTURE_MODE_ARB                0x884B
#endif /* GL_ARB_depth_texture */

#ifndef GL_ARB_framebuffer_object
#define GL_ARB_framebuffer_object                1
#endif /* GL_ARB_framebuffer_object */

#ifndef GL_ARB_occlusion_query
#define GL_ARB_occlusion_query                   1
#define GL_QUERY_COUNTER_BITS_ARB                0x8864
#define GL_CURRENT_QUERY_ARB                     0x8865
#define GL_QUERY_RESULT_ARB                      0x8866
#define GL_QUERY_RESULT_AVAILABLE_ARB            0x8867
#define GL_SAMPLES_PASSED_ARB                    0x8914
#endif /* GL_ARB_occlusion_query */

#ifndef GL_ARB_point_parameters
#define GL_ARB_point_parameters                  1
#define GL_POINT_SIZE_MIN_ARB                    0x8126
#define GL_POINT_SIZE_MAX_ARB                    0x8127
#define GL_POINT_FADE_THRESHOLD_SIZE_ARB         0x8128
#define GL_POINT_DISTANCE_ATTENUATION_ARB        0x8129
#endif /* GL_ARB_point_parameters */

#ifndef GL_ARB_shadow
#define GL_ARB_shadow                            1
#define GL_TEXTURE_COMPARE_MODE_ARB              0x884C
#define GL_TEXTURE_COMPARE_FUNC_ARB              0x884D
#define GL_COMPARE_R_TO_TEXTURE_ARB              0x884E
#endif /* GL_ARB_shadow */

#ifndef GL_ARB_texture_border_clamp
#define GL_ARB_texture_border_clamp              1
#define GL_CLAMP_TO_BORDER_ARB                   0x812D
#endif /* GL_ARB_texture_border_clamp */

#ifndef GL_ARB_texture_compression_rgtc
#define GL_ARB_texture_compression_rgtc          1
#define GL_COMPRESSED_RED_RGTC1                  0x8DBB
#define GL_COMPRESSED_SIGNED_RED_RGTC1           0x8DBC
#define GL_COMPRESSED_RG_RGTC2                   0x8DBD
#define GL_COMPRESSED_SIGNED_RG_RGTC2            0x8DBE
#endif /* GL_ARB_texture_compression_rgtc */

#ifndef GL_ARB_texture_cube_map
#define GL_ARB_texture_cube_map                  1
#define GL_NORMAL_MAP_ARB                        0x8511
#define GL_REFLECTION_MAP_ARB                    0x8512
#define GL_TEXTURE_CUBE_MAP_ARB                  0x8513
#define GL_TEXTURE_BINDING_CUBE_MAP_ARB          0x8514
#define GL_TEXTURE_CUBE_MAP_POSITIVE_X_ARB       0x8515
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_X_ARB       0x8516
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Y_ARB       0x8517
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Y_ARB       0x8518
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Z_ARB       0x8519
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_ARB       0x851A
#define GL_PROXY_TEXTURE_CUBE_MAP_ARB            0x851B
#define GL_MAX_CUBE_MAP_TEXTURE_SIZE_ARB         0x851C
#endif /* GL_ARB_texture_cube_map */

#ifndef GL_ARB_texture_env_add
#define GL_ARB_texture_env_add                   1
#endif /* GL_ARB_texture_env_add */

#ifndef GL_ARB_texture_env_combine
#define GL_ARB_texture_env_combine               1
#define GL_COMBINE_ARB                           0x8570
#define GL_COMBINE_RGB_ARB                       0x8571
#define GL_COMBINE_ALPHA_ARB                     0x8572
#define GL_SOURCE0_RGB_ARB                       0x8580
#define GL_SOURCE1_RGB_ARB                       0x8581
#define GL_SOURCE2_RGB_ARB                       0x8582
#define GL_SOURCE0_ALPHA_ARB                     0x8588
#define GL_SOURCE1_ALPHA_ARB                     0x8589
#define GL_SOURCE2_ALPHA_ARB                     0x858A
#define GL_OPERAND0_RGB_ARB                      0x8590
#define GL_OPERAND1_RGB_ARB                      0x8591
#define GL_OPERAND2_RGB_ARB                      0x8592
#define GL_OPERAND0_ALPHA_ARB                    0x8598
#define GL_OPERAND1_ALPHA_ARB                    0x8599
#define GL_OPERAND2_ALPHA_ARB                    0x859A
#define GL_RGB_SCALE_ARB                         0x8573
#define GL_ADD_SIGNED_ARB                        0x8574
#define GL_INTERPOLATE_ARB                       0x8575
#define GL_SUBTRACT_ARB                          0x84E7
#define GL_CONSTANT_ARB                          0x8576
#define GL_PRIMARY_COLOR_ARB                     0x8577
#define GL_PREVIOUS_ARB                          0x8578
#endif /* GL_ARB_texture_env_combine */

#ifndef GL_ARB_texture_env_crossbar
#define GL_ARB_texture_env_crossbar              1
#endif /* GL_ARB_texture_env_crossbar */

#ifndef GL_ARB_texture_env_dot3
#define GL_ARB_texture_env_dot3                  1
#define GL_DOT3_RGB_ARB                          0x86AE
#define GL_DOT3_RGBA_ARB                         0x86AF
#endif /* GL_ARB_texture_env_dot3 */

#ifndef GL_ARB_texture_mirrored_repeat
#define GL_ARB_texture_mirrored_repeat           1
#define GL_MIRRORED_REPEAT_ARB                   0x8370
#endif /* GL_ARB_texture_mirrored_repeat */

#ifndef GL_ARB_transpose_matrix
#define GL_ARB_transpose_matrix                  1
#define GL_TRANSPOSE_MODELVIEW_MATRIX_ARB        0x84E3
#define GL_TRANSPOSE_PROJECTION_MATRIX_ARB       0x84E4
#define GL_TRANSPOSE_TEXTURE_MATRIX_ARB          0x84E5
#define GL_TRANSPOSE_COLOR_MATRIX_ARB            0x84E6
#endif /* GL_ARB_transpose_matrix */

#ifndef GL_ARB_vertex_buffer_object
#define GL_ARB_vertex_buffer_object              1
#define GL_BUFFER_SIZE_ARB                       0x8764
#define GL_BUFFER_USAGE_ARB                      0x8765
#define GL_ARRAY_BUFFER_ARB                      0x8892
#define GL_ELEMENT_ARRAY_BUFFER_ARB              0x8893
#define GL_ARRAY_BUFFER_BINDING_ARB              0x8894
#define GL_ELEMENT_ARRAY_BUFFER_BINDING_ARB      0x8895
#define GL_VERTEX_ARRAY_BUFFER_BINDING_ARB       0x8896
#define GL_NORMAL_ARRAY_BUFFER_BINDING_ARB       0x8897
#define GL_COLOR_ARRAY_BUFFER_BINDING_ARB        0x8898
#define GL_INDEX_ARRAY_BUFFER_BINDING_ARB        0x8899
#define GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING_ARB 0x889A
#define GL_EDGE_FLAG_ARRAY_BUFFER_BINDING_ARB    0x889B
#define GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING_ARB 0x889C
#define GL_FOG_COORDINATE_ARRAY_BUFFER_BINDING_ARB 0x889D
#define GL_WEIGHT_ARRAY_BUFFER_BINDING_ARB       0x889E
#define GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING_ARB 0x889F
#define GL_READ_ONLY_ARB                         0x88B8
#define GL_WRITE_ONLY_ARB                        0x88B9
#define GL_READ_WRITE_ARB                        0x88BA
#define GL_BUFFER_ACCESS_ARB                     0x88BB
#define GL_BUFFER_MAPPED_ARB                     0x88BC
#define GL_BUFFER_MAP_POINTER_ARB                0x88BD
#define GL_STREAM_DRAW_ARB                       0x88E0
#define GL_STREAM_READ_ARB                       0x88E1
#define GL_STREAM_COPY_ARB                       0x88E2
#define GL_STATIC_DRAW_ARB                       0x88E4
#define GL_STATIC_READ_ARB                       0x88E5
#define GL_STATIC_COPY_ARB                       0x88E6
#define GL_DYNAMIC_DRAW_ARB                      0x88E8
#define GL_DYNAMIC_READ_ARB                      0x88E9
#define GL_DYNAMIC_COPY_ARB                      0x88EA
#endif /* GL_ARB_vertex_buffer_object */

#ifndef GL_ARB_window_pos
#define GL_ARB_window_pos                        1
#endif /* GL_ARB_window_pos */

#ifndef GL_EXT_abgr
#define GL_EXT_abgr                              1
#define GL_ABGR_EXT                              0x8000
#endif /* GL_EXT_abgr */

#ifndef GL_EXT_bgra
#define GL_EXT_bgra                              1
#define GL_BGR_EXT                               0x80E0
#define GL_BGRA_EXT                              0x80E1
#endif /* GL_EXT_bgra */

#ifndef GL_EXT_blend_color
#define GL_EXT_blend_color                       1
#define GL_CONSTANT_COLOR_EXT                    0x8001
#define GL_ONE_MINUS_CONSTANT_COLOR_EXT          0x8002
#define GL_CONSTANT_ALPHA_EXT                    0x8003
#define GL_ONE_MINUS_CONSTANT_ALPHA_EXT          0x8004
#define GL_BLEND_COLOR_EXT                       0x8005
#endif /* GL_EXT_blend_color */

#ifndef GL_EXT_blend_func_separate
#define GL_EXT_blend_func_separate               1
#define GL_BLEND_DST_RGB_EXT                     0x80C8
#define GL_BLEND_SRC_RGB_EXT                     0x80C9
#define GL_BLEND_DST_ALPHA_EXT                   0x80CA
#define GL_BLEND_SRC_ALPHA_EXT                   0x80CB
#endif /* GL_EXT_blend_func_separate */

#ifndef GL_EXT_blend_minmax
#define GL_EXT_blend_minmax                      1
#define GL_MIN_EXT                               0x8007
#define GL_MAX_EXT                               0x8008
#define GL_FUNC_ADD_EXT                          0x8006
#define GL_BLEND_EQUATION_EXT                    0x8009
#endif /* GL_EXT_blend_minmax */

#ifndef GL_EXT_blend_subtract
#define GL_EXT_blend_subtract                    1
#define GL_FUNC_SUBTRACT_EXT                     0x800A
#define GL_FUNC_REVERSE_SUBTRACT_EXT             0x800B
#endif /* GL_EXT_blend_subtract */

#ifndef GL_EXT_draw_range_elements
#define GL_EXT_draw_range_elements               1
#define GL_MAX_ELEMENTS_VERTICES_EXT             0x80E8
#define GL_MAX_ELEMENTS_INDICES_EXT              0x80E9
#endif /* GL_EXT_draw_range_elements */

#ifndef GL_EXT_fog_coord
#define GL_EXT_fog_coord                         1
#define GL_FOG_COORDINATE_SOURCE_EXT             0x8450
#define GL_FOG_COORDINATE_EXT                    0x8451
#define GL_FRAGMENT_DEPTH_EXT                    0x8452
#define GL_CURRENT_FOG_COORDINATE_EXT            0x8453
#define GL_FOG_COORDINATE_ARRAY_TYPE_EXT         0x8454
#define GL_FOG_COORDINATE_ARRAY_STRIDE_EXT       0x8455
#define GL_FOG_COORDINATE_ARRAY_POINTER_EXT      0x8456
#define GL_FOG_COORDINATE_ARRAY_EXT              0x8457
#endif /* GL_EXT_fog_coord */

#ifndef GL_EXT_framebuffer_blit
#define GL_EXT_framebuffer_blit                  1
#define GL_READ_FRAMEBUFFER_EXT                  0x8CA8
#define GL_DRAW_FRAMEBUFFER_EXT                  0x8CA9
#define GL_DRAW_FRAMEBUFFER_BINDING_EXT          0x8CA6
#define GL_READ_FRAMEBUFFER_BINDING_EXT          0x8CAA
#endif /* GL_EXT_framebuffer_blit */

#ifndef GL_EXT_framebuffer_multisample
#define GL_EXT_framebuffer_multisample           1
#define GL_RENDERBUFFER_SAMPLES_EXT              0x8CAB
#define GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE_EXT 0x8D56
#define GL_MAX_SAMPLES_EXT                       0x8D57
#endif /* GL_EXT_framebuffer_multisample */

#ifndef GL_EXT_framebuffer_object
#define GL_EXT_framebuffer_object                1
#define GL_INVALID_FRAMEBUFFER_OPERATION_EXT     0x0506
#define GL_MAX_RENDERBUFFER_SIZE_EXT             0x84E8
#define GL_FRAMEBUFFER_BINDING_EXT               0x8CA6
#define GL_RENDERBUFFER_BINDING_EXT              0x8CA7
#define GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT 0x8CD0
#define GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT 0x8CD1
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT 0x8CD2
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT 0x8CD3
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT 0x8CD4
#define GL_FRAMEBUFFER_COMPLETE_EXT              0x8CD5
#define GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT 0x8CD6
#define GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT 0x8CD7
#define GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT 0x8CD9
#define GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT    0x8CDA
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT 0x8CDB
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT 0x8CDC
#define GL_FRAMEBUFFER_UNSUPPORTED_EXT           0x8CDD
#define GL_MAX_COLOR_ATTACHMENTS_EXT             0x8CDF
#define GL_COLOR_ATTACHMENT0_EXT                 0x8CE0
#define GL_COLOR_ATTACHMENT1_EXT                 0x8CE1
#define GL_COLOR_ATTACHMENT2_EXT                 0x8CE2
#define GL_COLOR_ATTACHMENT3_EXT                 0x8CE3
#define GL_COLOR_ATTACHMENT4_EXT                 0x8CE4
#define GL_COLOR_ATTACHMENT5_EXT                 0x8CE5
#define GL_COLOR_ATTACHMENT6_EXT                 0x8CE6
#define GL_COLOR_ATTACHMENT7_EXT                 0x8CE7
#define GL_COLOR_ATTACHMENT8_EXT                 0x8CE8
#define GL_COLOR_ATTACHMENT9_EXT                 0x8CE9
#define GL_COLOR_ATTACHMENT10_EXT                0x8CEA
#define GL_COLOR_ATTACHMENT11_EXT                0x8CEB
#define GL_COLOR_ATTACHMENT12_EXT                0x8CEC
#define GL_COLOR_ATTACHMENT13_EXT                0x8CED
#define GL_COLOR_ATTACHMENT14_EXT                0x8CEE
#define GL_COLOR_ATTACHMENT15_EXT                0x8CEF
#define GL_DEPTH_ATTACHMENT_EXT                  0x8D00
#define GL_STENCIL_ATTACHMENT_EXT                0x8D20
#define GL_FRAMEBUFFER_EXT                       0x8D40
#define GL_RENDERBUFFER_EXT                      0x8D41
#define GL_RENDERBUFFER_WIDTH_EXT                0x8D42
#define GL_RENDERBUFFER_HEIGHT_EXT               0x8D43
#define GL_RENDERBUFFER_INTERNAL_FORMAT_EXT      0x8D44
#define GL_STENCIL_INDEX1_EXT                    0x8D46
#define GL_STENCIL_INDEX4_EXT                    0x8D47
#define GL_STENCIL_INDEX8_EXT                    0x8D48
#define GL_STENCIL_INDEX16_EXT                   0x8D49
#define GL_RENDERBUFFER_RED_SIZE_EXT             0x8D50
#define GL_RENDERBUFFER_GREEN_SIZE_EXT           0x8D51
#define GL_RENDERBUFFER_BLUE_SIZE_EXT            0x8D52
#define GL_RENDERBUFFER_ALPHA_SIZE_EXT           0x8D53
#define GL_RENDERBUFFER_DEPTH_SIZE_EXT           0x8D54
#define GL_RENDERBUFFER_STENCIL_SIZE_EXT         0x8D55
#endif /* GL_EXT_framebuffer_object */

#ifndef GL_EXT_multi_draw_arrays
#define GL_EXT_multi_draw_arrays                 1
#endif /* GL_EXT_multi_draw_arrays */

#ifndef GL_EXT_packed_depth_stencil
#define GL_EXT_packed_depth_stencil              1
#define GL_DEPTH_STENCIL_EXT                     0x84F9
#define GL_UNSIGNED_INT_24_8_EXT                 0x84FA
#define GL_DEPTH24_STENCIL8_EXT                  0x88F0
#define GL_TEXTURE_STENCIL_SIZE_EXT              0x88F1
#endif /* GL_EXT_packed_depth_stencil */

#ifndef GL_EXT_packed_pixels
#define GL_EXT_packed_pixels                     1
#define GL_UNSIGNED_BYTE_3_3_2_EXT               0x8032
#define GL_UNSIGNED_SHORT_4_4_4_4_EXT            0x8033
#define GL_UNSIGNED_SHORT_5_5_5_1_EXT            0x8034
#define GL_UNSIGNED_INT_8_8_8_8_EXT              0x8035
#define GL_UNSIGNED_INT_10_10_10_2_EXT           0x8036
#endif /* GL_EXT_packed_pixels */

#ifndef GL_EXT_point_parameters
#define GL_EXT_point_parameters                  1
#define GL_POINT_SIZE_MIN_EXT                    0x8126
#define GL_POINT_SIZE_MAX_EXT                    0x8127
#define GL_POINT_FADE_THRESHOLD_SIZE_EXT         0x8128
#define GL_DISTANCE_ATTENUATION_EXT              0x8129
#endif /* GL_EXT_point_parameters */

#ifndef GL_EXT_rescale_normal
#define GL_EXT_rescale_normal                    1
#define GL_RESCALE_NORMAL_EXT                    0x803A
#endif /* GL_EXT_rescale_normal */

#ifndef GL_EXT_secondary_color
#define GL_EXT_secondary_color                   1
#define GL_COLOR_SUM_EXT                         0x8458
#define GL_CURRENT_SECONDARY_COLOR_EXT           0x8459
#define GL_SECONDARY_COLOR_ARRAY_SIZE_EXT        0x845A
#define GL_SECONDARY_COLOR_ARRAY_TYPE_EXT        0x845B
#define GL_SECONDARY_COLOR_ARRAY_STRIDE_EXT      0x845C
#define GL_SECONDARY_COLOR_ARRAY_POINTER_EXT     0x845D
#define GL_SECONDARY_COLOR_ARRAY_EXT             0x845E
#endif /* GL_EXT_secondary_color */

#ifndef GL_EXT_separate_specular_color
#define GL_EXT_separate_specular_color           1
#define GL_LIGHT_MODEL_COLOR_CONTROL_EXT         0x81F8
#define GL_SINGLE_COLOR_EXT                      0x81F9
#define GL_SEPARATE_SPECULAR_COLOR_EXT           0x81FA
#endif /* GL_EXT_separate_specular_color */

#ifndef GL_EXT_stencil_wrap
#define GL_EXT_stencil_wrap                      1
#define GL_INCR_WRAP_EXT                         0x8507
#define GL_DECR_WRAP_EXT                         0x8508
#endif /* GL_EXT_stencil_wrap */

#ifndef GL_EXT_texture3D
#define GL_EXT_texture3D                         1
#define GL_PACK_SKIP_IMAGES_EXT                  0x806B
#define GL_PACK_IMAGE_HEIGHT_EXT                 0x806C
#define GL_UNPACK_SKIP_IMAGES_EXT                0x806D
#define GL_UNPACK_IMAGE_HEIGHT_EXT               0x806E
#define GL_TEXTURE_3D_EXT                        0x806F
#define GL_PROXY_TEXTURE_3D_EXT                  0x8070
#define GL_TEXTURE_DEPTH_EXT                     0x8071
#define GL_TEXTURE_WRAP_R_EXT                    0x8072
#define GL_MAX_3D_TEXTURE_SIZE_EXT               0x8073
#endif /* GL_EXT_texture3D */

#ifndef GL_EXT_texture_compression_latc
#define GL_EXT_texture_compression_latc          1
#define GL_COMPRESSED_LUMINANCE_LATC1_EXT        0x8C70
#define GL_COMPRESSED_SIGNED_LUMINANCE_LATC1_EXT 0x8C71
#define GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT  0x8C72
#define GL_COMPRESSED_SIGNED_LUMINANCE_ALPHA_LATC2_EXT 0x8C73
#endif /* GL_EXT_texture_compression_latc */

#ifndef GL_EXT_texture_compression_rgtc
#define GL_EXT_texture_compression_rgtc          1
#define GL_COMPRESSED_RED_RGTC1_EXT              0x8DBB
#define GL_COMPRESSED_SIGNED_RED_RGTC1_EXT       0x8DBC
#define GL_COMPRESSED_RED_GREEN_RGTC2_EXT        0x8DBD
#define GL_COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT 0x8DBE
#endif /* GL_EXT_texture_compression_rgtc */

#ifndef GL_EXT_texture_compression_s3tc
#define GL_EXT_texture_compression_s3tc          1
#define GL_COMPRESSED_RGB_S3TC_DXT1_EXT          0x83F0
#define GL_COMPRESSED_RGBA_S3TC_DXT1_EXT         0x83F1
#define GL_COMPRESSED_RGBA_S3TC_DXT3_EXT         0x83F2
#define GL_COMPRESSED_RGBA_S3TC_DXT5_EXT         0x83F3
#endif /* GL_EXT_texture_compression_s3tc */

#ifndef GL_EXT_texture_env_add
#define GL_EXT_texture_env_add                   1
#endif /* GL_EXT_texture_env_add */

#ifndef GL_EXT_texture_env_combine
#define GL_EXT_texture_env_combine               1
#define GL_COMBINE_EXT                           0x8570
#define GL_COMBINE_RGB_EXT                       0x8571
#define GL_COMBINE_ALPHA_EXT                     0x8572
#define GL_RGB_SCALE_EXT                         0x8573
#define GL_ADD_SIGNED_EXT                        0x8574
#define GL_INTERPOLATE_EXT                       0x8575
#define GL_CONSTANT_EXT                          0x8576
#define GL_PRIMARY_COLOR_EXT                     0x8577
#define GL_PREVIOUS_EXT                          0x8578
#define GL_SOURCE0_RGB_EXT                       0x8580
#define GL_SOURCE1_RGB_EXT                       0x8581
#define GL_SOURCE2_RGB_EXT                       0x8582
#define GL_SOURCE0_ALPHA_EXT                     0x8588
#define GL_SOURCE1_ALPHA_EXT                     0x8589
#define GL_SOURCE2_ALPHA_EXT                     0x858A
#define GL_OPERAND0_RGB_EXT                      0x8590
#define GL_OPERAND1_RGB_EXT                      0x8591
#define GL_OPERAND2_RGB_EXT                      0x8592
#define GL_OPERAND0_ALPHA_EXT                    0x8598
#define GL_OPERAND1_ALPHA_EXT                    0x8599
#define GL_OPERAND2_ALPHA_EXT                    0x859A
#endif /* GL_EXT_texture_env_combine */

#ifndef GL_EXT_texture_filter_anisotropic
#define GL_EXT_texture_filter_anisotropic        1
#define GL_TEXTURE_MAX_ANISOTROPY_EXT            0x84FE
#define GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT        0x84FF
#endif /* GL_EXT_texture_filter_anisotropic */

#ifndef GL_EXT_texture_lod_bias
#define GL_EXT_texture_lod_bias                  1
#define GL_MAX_TEXTURE_LOD_BIAS_EXT              0x84FD
#define GL_TEXTURE_FILTER_CONTROL_EXT            0x8500
#define GL_TEXTURE_LOD_BIAS_EXT                  0x8501
#endif /* GL_EXT_texture_lod_bias */

#ifndef GL_EXT_texture_sRGB
#define GL_EXT_texture_sRGB                      1
#define GL_SRGB_EXT                              0x8C40
#define GL_SRGB8_EXT                             0x8C41
#define GL_SRGB_ALPHA_EXT                        0x8C42
#define GL_SRGB8_ALPHA8_EXT                      0x8C43
#define GL_SLUMINANCE_ALPHA_EXT                  0x8C44
#define GL_SLUMINANCE8_ALPHA8_EXT                0x8C45
#define GL_SLUMINANCE_EXT                        0x8C46
#define GL_SLUMINANCE8_EXT                       0x8C47
#define GL_COMPRESSED_SRGB_EXT                   0x8C48
#define GL_COMPRESSED_SRGB_ALPHA_EXT             0x8C49
#define GL_COMPRESSED_SLUMINANCE_EXT             0x8C4A
#define GL_COMPRESSED_SLUMINANCE_ALPHA_EXT       0x8C4B
#define GL_COMPRESSED_SRGB_S3TC_DXT1_EXT         0x8C4C
#define GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT   0x8C4D
#define GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT   0x8C4E
#define GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT   0x8C4F
#endif /* GL_EXT_texture_sRGB */

#ifndef GL_NV_blend_square
#define GL_NV_blend_square                       1
#endif /* GL_NV_blend_square */

#ifndef GL_SGIS_generate_mipmap
#define GL_SGIS_generate_mipmap                  1
#define GL_GENERATE_MIPMAP_SGIS                  0x8191
#define GL_GENERATE_MIPMAP_HINT_SGIS             0x8192
#endif /* GL_SGIS_generate_mipmap */

#ifndef GL_SGIS_texture_edge_clamp
#define GL_SGIS_texture_edge_clamp               1
#define GL_CLAMP_TO_EDGE_SGIS                    0x812F
#endif /* GL_SGIS_texture_edge_clamp */

#define GL_BLEND_EQUATION_RGB                    0x8009
#define GL_STENCIL_BACK_FUNC                     0x8800
#define GL_STENCIL_BACK_FAIL                     0x8801
#define GL_STENCIL_BACK_PASS_DEPTH_FAIL          0x8802
#define GL_STENCIL_BACK_PASS_DEPTH_PASS          0x8803
#define GL_BLEND_EQUATION_ALPHA                  0x883D
#define GL_STENCIL_BACK_REF                      0x8CA3
#define GL_STENCIL_BACK_VALUE_MASK               0x8CA4
#define GL_STENCIL_BACK_WRITEMASK                0x8CA5
#define GL_INVALID_FRAMEBUFFER_OPERATION         0x0506
#define GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING 0x8210
#define GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE 0x8211
#define GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE       0x8212
#define GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE     0x8213
#define GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE      0x8214
#define GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE     0x8215
#define GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE     0x8216
#define GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE   0x8217
#define GL_FRAMEBUFFER_DEFAULT                   0x8218
#define GL_FRAMEBUFFER_UNDEFINED                 0x8219
#define GL_DEPTH_STENCIL_ATTACHMENT              0x821A
#define GL_MAX_RENDERBUFFER_SIZE                 0x84E8
#define GL_DEPTH_STENCIL                         0x84F9
#define GL_UNSIGNED_INT_24_8                     0x84FA
#define GL_DEPTH24_STENCIL8                      0x88F0
#define GL_TEXTURE_STENCIL_SIZE                  0x88F1
#define GL_TEXTURE_RED_TYPE                      0x8C10
#define GL_TEXTURE_GREEN_TYPE                    0x8C11
#define GL_TEXTURE_BLUE_TYPE                     0x8C12
#define GL_TEXTURE_ALPHA_TYPE                    0x8C13
#define GL_TEXTURE_DEPTH_TYPE                    0x8C16
#define GL_UNSIGNED_NORMALIZED                   0x8C17
#define GL_FRAMEBUFFER_BINDING                   0x8CA6
#define GL_DRAW_FRAMEBUFFER_BINDING              0x8CA6
#define GL_RENDERBUFFER_BINDING                  0x8CA7
#define GL_READ_FRAMEBUFFER                      0x8CA8
#define GL_DRAW_FRAMEBUFFER                      0x8CA9
#define GL_READ_FRAMEBUFFER_BINDING              0x8CAA
#define GL_RENDERBUFFER_SAMPLES                  0x8CAB
#define GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE    0x8CD0
#define GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME    0x8CD1
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL  0x8CD2
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE 0x8CD3
#define GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER  0x8CD4
#define GL_FRAMEBUFFER_COMPLETE                  0x8CD5
#define GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT     0x8CD6
#define GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT 0x8CD7
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER    0x8CDB
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER    0x8CDC
#define GL_FRAMEBUFFER_UNSUPPORTED               0x8CDD
#define GL_MAX_COLOR_ATTACHMENTS                 0x8CDF
#define GL_COLOR_ATTACHMENT0                     0x8CE0
#define GL_COLOR_ATTACHMENT1                     0x8CE1
#define GL_COLOR_ATTACHMENT2                     0x8CE2
#define GL_COLOR_ATTACHMENT3                     0x8CE3
#define GL_COLOR_ATTACHMENT4                     0x8CE4
#define GL_COLOR_ATTACHMENT5                     0x8CE5
#define GL_COLOR_ATTACHMENT6                     0x8CE6
#define GL_COLOR_ATTACHMENT7                     0x8CE7
#define GL_COLOR_ATTACHMENT8                     0x8CE8
#define GL_COLOR_ATTACHMENT9                     0x8CE9
#define GL_COLOR_ATTACHMENT10                    0x8CEA
#define GL_COLOR_ATTACHMENT11                    0x8CEB
#define GL_COLOR_ATTACHMENT12                    0x8CEC
#define GL_COLOR_ATTACHMENT13                    0x8CED
#define GL_COLOR_ATTACHMENT14                    0x8CEE
#define GL_COLOR_ATTACHMENT15                    0x8CEF
#define GL_COLOR_ATTACHMENT16                    0x8CF0
#define GL_COLOR_ATTACHMENT17                    0x8CF1
#define GL_COLOR_ATTACHMENT18                    0x8CF2
#define GL_COLOR_ATTACHMENT19                    0x8CF3
#define GL_COLOR_ATTACHMENT20                    0x8CF4
#define GL_COLOR_ATTACHMENT21                    0x8CF5
#define GL_COLOR_ATTACHMENT22                    0x8CF6
#define GL_COLOR_ATTACHMENT23                    0x8CF7
#define GL_COLOR_ATTACHMENT24                    0x8CF8
#define GL_COLOR_ATTACHMENT25                    0x8CF9
#define GL_COLOR_ATTACHMENT26                    0x8CFA
#define GL_COLOR_ATTACHMENT27                    0x8CFB
#define GL_COLOR_ATTACHMENT28                    0x8CFC
#define GL_COLOR_ATTACHMENT29                    0x8CFD
#define GL_COLOR_ATTACHMENT30                    0x8CFE
#define GL_COLOR_ATTACHMENT31                    0x8CFF
#define GL_DEPTH_ATTACHMENT                      0x8D00
#define GL_STENCIL_ATTACHMENT                    0x8D20
#define GL_FRAMEBUFFER                           0x8D40
#define GL_RENDERBUFFER                          0x8D41
#define GL_RENDERBUFFER_WIDTH                    0x8D42
#define GL_RENDERBUFFER_HEIGHT                   0x8D43
#define GL_RENDERBUFFER_INTERNAL_FORMAT          0x8D44
#define GL_STENCIL_INDEX1                        0x8D46
#define GL_STENCIL_INDEX4                        0x8D47
#define GL_STENCIL_INDEX8                        0x8D48
#define GL_STENCIL_INDEX16                       0x8D49
#define GL_RENDERBUFFER_RED_SIZE                 0x8D50
#define GL_RENDERBUFFER_GREEN_SIZE               0x8D51
#define GL_RENDERBUFFER_BLUE_SIZE                0x8D52
#define GL_RENDERBUFFER_ALPHA_SIZE               0x8D53
#define GL_RENDERBUFFER_DEPTH_SIZE               0x8D54
#define GL_RENDERBUFFER_STENCIL_SIZE             0x8D55
#define GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE    0x8D56
#define GL_MAX_SAMPLES                           0x8D57
#define GL_INDEX                                 0x8222
#define GL_TEXTURE_LUMINANCE_TYPE                0x8C14
#define GL_TEXTURE_INTENSITY_TYPE                0x8C15
#define GL_SRGB                                  0x8C40
#define GL_SRGB8                                 0x8C41
#define GL_SRGB_ALPHA                            0x8C42
#define GL_SRGB8_ALPHA8                          0x8C43
#define GL_COMPRESSED_SRGB                       0x8C48
#define GL_COMPRESSED_SRGB_ALPHA                 0x8C49
#define GL_SLUMINANCE_ALPHA                      0x8C44
#define GL_SLUMINANCE8_ALPHA8                    0x8C45
#define GL_SLUMINANCE                            0x8C46
#define GL_SLUMINANCE8                           0x8C47
#define GL_COMPRESSED_SLUMINANCE                 0x8C4A
#define GL_COMPRESSED_SLUMINANCE_ALPHA           0x8C4B

/* Function-pointer types: src/ffi/multidraw.rs */
typedef void (APIENTRYP PFNGLMULTIDRAWARRAYSPROC) (GLenum mode, const GLint *first, const GLsizei *count, GLsizei drawcount);
typedef void (APIENTRYP PFNGLMULTIDRAWELEMENTSPROC) (GLenum mode, const GLsizei *count, GLenum type, const GLvoid *const *indices, GLsizei drawcount);

/* Function-pointer types: src/ffi/buffers.rs */
typedef void (APIENTRYP PFNGLGENBUFFERSPROC) (GLsizei n, GLuint *buffers);
typedef void (APIENTRYP PFNGLDELETEBUFFERSPROC) (GLsizei n, const GLuint *buffers);
typedef GLboolean (APIENTRYP PFNGLISBUFFERPROC) (GLuint buffer);
typedef void (APIENTRYP PFNGLBINDBUFFERPROC) (GLenum target, GLuint buffer);
typedef void (APIENTRYP PFNGLBUFFERDATAPROC) (GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage);
typedef void (APIENTRYP PFNGLBUFFERSUBDATAPROC) (GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid *data);
typedef void (APIENTRYP PFNGLGETBUFFERSUBDATAPROC) (GLenum target, GLintptr offset, GLsizeiptr size, GLvoid *data);
typedef GLvoid *(APIENTRYP PFNGLMAPBUFFERPROC) (GLenum target, GLenum access);
typedef GLboolean (APIENTRYP PFNGLUNMAPBUFFERPROC) (GLenum target);
typedef void (APIENTRYP PFNGLGETBUFFERPARAMETERIVPROC) (GLenum target, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETBUFFERPOINTERVPROC) (GLenum target, GLenum pname, GLvoid **params);

/* Function-pointer types: src/ffi/fragment_ext.rs */
typedef void (APIENTRYP PFNGLBLENDFUNCSEPARATEPROC) (GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
typedef void (APIENTRYP PFNGLBLENDEQUATIONSEPARATEPROC) (GLenum modeRGB, GLenum modeAlpha);
typedef void (APIENTRYP PFNGLSTENCILFUNCSEPARATEPROC) (GLenum face, GLenum func, GLint ref, GLuint mask);
typedef void (APIENTRYP PFNGLSTENCILOPSEPARATEPROC) (GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass);
typedef void (APIENTRYP PFNGLSTENCILMASKSEPARATEPROC) (GLenum face, GLuint mask);
typedef void (APIENTRYP PFNGLBLENDFUNCSEPARATEEXTPROC) (GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
typedef void (APIENTRYP PFNGLBLENDEQUATIONSEPARATEEXTPROC) (GLenum modeRGB, GLenum modeAlpha);
typedef void (APIENTRYP PFNGLBLENDEQUATIONEXTPROC) (GLenum mode);
typedef void (APIENTRYP PFNGLBLENDCOLOREXTPROC) (GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha);

/* Function-pointer types: src/ffi/textures_ext.rs */
typedef void (APIENTRYP PFNGLGENERATEMIPMAPPROC) (GLenum target);
typedef void (APIENTRYP PFNGLGENERATEMIPMAPEXTPROC) (GLenum target);

/* Function-pointer types: src/ffi/framebuffers.rs */
typedef void (APIENTRYP PFNGLGENFRAMEBUFFERSPROC) (GLsizei n, GLuint *framebuffers);
typedef void (APIENTRYP PFNGLDELETEFRAMEBUFFERSPROC) (GLsizei n, const GLuint *framebuffers);
typedef void (APIENTRYP PFNGLBINDFRAMEBUFFERPROC) (GLenum target, GLuint framebuffer);
typedef void (APIENTRYP PFNGLBINDFRAMEBUFFEREXTPROC) (GLenum target, GLuint framebuffer);
typedef GLboolean (APIENTRYP PFNGLISFRAMEBUFFERPROC) (GLuint framebuffer);
typedef GLenum (APIENTRYP PFNGLCHECKFRAMEBUFFERSTATUSPROC) (GLenum target);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE1DPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE2DPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE3DPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level, GLint zoffset);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURELAYERPROC) (GLenum target, GLenum attachment, GLuint texture, GLint level, GLint layer);
typedef void (APIENTRYP PFNGLFRAMEBUFFERRENDERBUFFERPROC) (GLenum target, GLenum attachment, GLenum renderbuffertarget, GLuint renderbuffer);
typedef void (APIENTRYP PFNGLGENRENDERBUFFERSPROC) (GLsizei n, GLuint *renderbuffers);
typedef void (APIENTRYP PFNGLDELETERENDERBUFFERSPROC) (GLsizei n, const GLuint *renderbuffers);
typedef void (APIENTRYP PFNGLBINDRENDERBUFFERPROC) (GLenum target, GLuint renderbuffer);
typedef void (APIENTRYP PFNGLBINDRENDERBUFFEREXTPROC) (GLenum target, GLuint renderbuffer);
typedef GLboolean (APIENTRYP PFNGLISRENDERBUFFERPROC) (GLuint renderbuffer);
typedef void (APIENTRYP PFNGLRENDERBUFFERSTORAGEPROC) (GLenum target, GLenum internalformat, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC) (GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLGETRENDERBUFFERPARAMETERIVPROC) (GLenum target, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC) (GLenum target, GLenum attachment, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLBLITFRAMEBUFFERPROC) (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);
typedef void (APIENTRYP PFNGLBLITFRAMEBUFFEREXTPROC) (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);

/* Function-pointer types: src/ffi/lighting_ext.rs */
typedef void (APIENTRYP PFNGLFOGCOORDFPROC) (GLfloat coord);
typedef void (APIENTRYP PFNGLFOGCOORDDPROC) (GLdouble coord);
typedef void (APIENTRYP PFNGLFOGCOORDFVPROC) (const GLfloat *coord);
typedef void (APIENTRYP PFNGLFOGCOORDDVPROC) (const GLdouble *coord);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BPROC) (GLbyte red, GLbyte green, GLbyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BVPROC) (const GLbyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SPROC) (GLshort red, GLshort green, GLshort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SVPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IPROC) (GLint red, GLint green, GLint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IVPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FPROC) (GLfloat red, GLfloat green, GLfloat blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FVPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DPROC) (GLdouble red, GLdouble green, GLdouble blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DVPROC) (const GLdouble *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBPROC) (GLubyte red, GLubyte green, GLubyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBVPROC) (const GLubyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USPROC) (GLushort red, GLushort green, GLushort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USVPROC) (const GLushort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIPROC) (GLuint red, GLuint green, GLuint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIVPROC) (const GLuint *v);

/* Function-pointer types: src/ffi/arrays_gl14.rs */
typedef void (APIENTRYP PFNGLSECONDARYCOLORPOINTERPROC) (GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
typedef void (APIENTRYP PFNGLFOGCOORDPOINTERPROC) (GLenum type, GLsizei stride, const GLvoid *pointer);

/* Function-pointer types: src/ffi/points.rs */
typedef void (APIENTRYP PFNGLPOINTPARAMETERFPROC) (GLenum pname, GLfloat param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFVPROC) (GLenum pname, const GLfloat *params);
typedef void (APIENTRYP PFNGLPOINTPARAMETERIPROC) (GLenum pname, GLint param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERIVPROC) (GLenum pname, const GLint *params);

/* Function-pointer types: src/ffi/pixels_ext.rs */
typedef void (APIENTRYP PFNGLWINDOWPOS2SPROC) (GLshort x, GLshort y);
typedef void (APIENTRYP PFNGLWINDOWPOS2SVPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2IPROC) (GLint x, GLint y);
typedef void (APIENTRYP PFNGLWINDOWPOS2IVPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2FPROC) (GLfloat x, GLfloat y);
typedef void (APIENTRYP PFNGLWINDOWPOS2FVPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2DPROC) (GLdouble x, GLdouble y);
typedef void (APIENTRYP PFNGLWINDOWPOS2DVPROC) (const GLdouble *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3SPROC) (GLshort x, GLshort y, GLshort z);
typedef void (APIENTRYP PFNGLWINDOWPOS3SVPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3IPROC) (GLint x, GLint y, GLint z);
typedef void (APIENTRYP PFNGLWINDOWPOS3IVPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3FPROC) (GLfloat x, GLfloat y, GLfloat z);
typedef void (APIENTRYP PFNGLWINDOWPOS3FVPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3DPROC) (GLdouble x, GLdouble y, GLdouble z);
typedef void (APIENTRYP PFNGLWINDOWPOS3DVPROC) (const GLdouble *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2SARBPROC) (GLshort x, GLshort y);
typedef void (APIENTRYP PFNGLWINDOWPOS2SVARBPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2IARBPROC) (GLint x, GLint y);
typedef void (APIENTRYP PFNGLWINDOWPOS2IVARBPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2FARBPROC) (GLfloat x, GLfloat y);
typedef void (APIENTRYP PFNGLWINDOWPOS2FVARBPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2DARBPROC) (GLdouble x, GLdouble y);
typedef void (APIENTRYP PFNGLWINDOWPOS2DVARBPROC) (const GLdouble *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3SARBPROC) (GLshort x, GLshort y, GLshort z);
typedef void (APIENTRYP PFNGLWINDOWPOS3SVARBPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3IARBPROC) (GLint x, GLint y, GLint z);
typedef void (APIENTRYP PFNGLWINDOWPOS3IVARBPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3FARBPROC) (GLfloat x, GLfloat y, GLfloat z);
typedef void (APIENTRYP PFNGLWINDOWPOS3FVARBPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3DARBPROC) (GLdouble x, GLdouble y, GLdouble z);
typedef void (APIENTRYP PFNGLWINDOWPOS3DVARBPROC) (const GLdouble *v);

/* Function-pointer types: src/ffi/queries.rs */
typedef void (APIENTRYP PFNGLGENQUERIESPROC) (GLsizei n, GLuint *ids);
typedef void (APIENTRYP PFNGLDELETEQUERIESPROC) (GLsizei n, const GLuint *ids);
typedef GLboolean (APIENTRYP PFNGLISQUERYPROC) (GLuint id);
typedef void (APIENTRYP PFNGLBEGINQUERYPROC) (GLenum target, GLuint id);
typedef void (APIENTRYP PFNGLENDQUERYPROC) (GLenum target);
typedef void (APIENTRYP PFNGLGETQUERYIVPROC) (GLenum target, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETQUERYOBJECTIVPROC) (GLuint id, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETQUERYOBJECTUIVPROC) (GLuint id, GLenum pname, GLuint *params);
typedef void (APIENTRYP PFNGLGENQUERIESARBPROC) (GLsizei n, GLuint *ids);
typedef void (APIENTRYP PFNGLDELETEQUERIESARBPROC) (GLsizei n, const GLuint *ids);
typedef GLboolean (APIENTRYP PFNGLISQUERYARBPROC) (GLuint id);
typedef void (APIENTRYP PFNGLBEGINQUERYARBPROC) (GLenum target, GLuint id);
typedef void (APIENTRYP PFNGLENDQUERYARBPROC) (GLenum target);
typedef void (APIENTRYP PFNGLGETQUERYIVARBPROC) (GLenum target, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETQUERYOBJECTIVARBPROC) (GLuint id, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETQUERYOBJECTUIVARBPROC) (GLuint id, GLenum pname, GLuint *params);

/* Function-pointer types: src/ffi/arrays_ext.rs */
typedef void (APIENTRYP PFNGLINDEXPOINTEREXTPROC) (GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
typedef void (APIENTRYP PFNGLVERTEXPOINTEREXTPROC) (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
typedef void (APIENTRYP PFNGLCOLORPOINTEREXTPROC) (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
typedef void (APIENTRYP PFNGLNORMALPOINTEREXTPROC) (GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
typedef void (APIENTRYP PFNGLTEXCOORDPOINTEREXTPROC) (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
typedef void (APIENTRYP PFNGLEDGEFLAGPOINTEREXTPROC) (GLsizei stride, GLsizei count, const GLboolean *ptr);

/* Function-pointer types: src/ffi/transform_ext.rs */
typedef void (APIENTRYP PFNGLCLIPCONTROLPROC) (GLenum origin, GLenum depth);

/* Function-pointer types: src/ffi/aliases_ext.rs */
typedef void (APIENTRYP PFNGLARRAYELEMENTEXTPROC) (GLint i);
typedef void (APIENTRYP PFNGLBINDBUFFERARBPROC) (GLenum target, GLuint buffer);
typedef void (APIENTRYP PFNGLBINDTEXTUREEXTPROC) (GLenum target, GLuint texture);
typedef void (APIENTRYP PFNGLBUFFERDATAARBPROC) (GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage);
typedef void (APIENTRYP PFNGLBUFFERSUBDATAARBPROC) (GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid *data);
typedef GLenum (APIENTRYP PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC) (GLenum target);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE1DARBPROC) (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLint border, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE2DARBPROC) (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLint border, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE3DARBPROC) (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE1DARBPROC) (GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE2DARBPROC) (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE3DARBPROC) (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLsizei image_size, const GLvoid *data);
typedef void (APIENTRYP PFNGLCOPYTEXSUBIMAGE3DEXTPROC) (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLDELETEBUFFERSARBPROC) (GLsizei n, const GLuint *buffers);
typedef void (APIENTRYP PFNGLDELETEFRAMEBUFFERSEXTPROC) (GLsizei n, const GLuint *framebuffers);
typedef void (APIENTRYP PFNGLDELETERENDERBUFFERSEXTPROC) (GLsizei n, const GLuint *renderbuffers);
typedef void (APIENTRYP PFNGLDRAWARRAYSEXTPROC) (GLenum mode, GLint first, GLsizei count);
typedef void (APIENTRYP PFNGLDRAWRANGEELEMENTSEXTPROC) (GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const GLvoid *indices);
typedef void (APIENTRYP PFNGLFOGCOORDPOINTEREXTPROC) (GLenum type, GLsizei stride, const GLvoid *pointer);
typedef void (APIENTRYP PFNGLFOGCOORDDEXTPROC) (GLdouble coord);
typedef void (APIENTRYP PFNGLFOGCOORDDVEXTPROC) (const GLdouble *coord);
typedef void (APIENTRYP PFNGLFOGCOORDFEXTPROC) (GLfloat coord);
typedef void (APIENTRYP PFNGLFOGCOORDFVEXTPROC) (const GLfloat *coord);
typedef void (APIENTRYP PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC) (GLenum target, GLenum attachment, GLenum renderbuffertarget, GLuint renderbuffer);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE1DEXTPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE2DEXTPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURE3DEXTPROC) (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level, GLint zoffset);
typedef void (APIENTRYP PFNGLFRAMEBUFFERTEXTURELAYEREXTPROC) (GLenum target, GLenum attachment, GLuint texture, GLint level, GLint layer);
typedef void (APIENTRYP PFNGLGENBUFFERSARBPROC) (GLsizei n, GLuint *buffers);
typedef void (APIENTRYP PFNGLGENFRAMEBUFFERSEXTPROC) (GLsizei n, GLuint *framebuffers);
typedef void (APIENTRYP PFNGLGENRENDERBUFFERSEXTPROC) (GLsizei n, GLuint *renderbuffers);
typedef void (APIENTRYP PFNGLGETBUFFERPARAMETERIVARBPROC) (GLenum target, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETBUFFERPOINTERVARBPROC) (GLenum target, GLenum pname, GLvoid **params);
typedef void (APIENTRYP PFNGLGETBUFFERSUBDATAARBPROC) (GLenum target, GLintptr offset, GLsizeiptr size, GLvoid *data);
typedef void (APIENTRYP PFNGLGETCOMPRESSEDTEXIMAGEARBPROC) (GLenum target, GLint level, GLvoid *img);
typedef void (APIENTRYP PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVEXTPROC) (GLenum target, GLenum attachment, GLenum pname, GLint *params);
typedef void (APIENTRYP PFNGLGETPOINTERVEXTPROC) (GLenum pname, GLvoid **params);
typedef void (APIENTRYP PFNGLGETRENDERBUFFERPARAMETERIVEXTPROC) (GLenum target, GLenum pname, GLint *params);
typedef GLboolean (APIENTRYP PFNGLISBUFFERARBPROC) (GLuint buffer);
typedef GLboolean (APIENTRYP PFNGLISFRAMEBUFFEREXTPROC) (GLuint framebuffer);
typedef GLboolean (APIENTRYP PFNGLISRENDERBUFFEREXTPROC) (GLuint renderbuffer);
typedef void (APIENTRYP PFNGLLOADTRANSPOSEMATRIXDARBPROC) (const GLdouble *m);
typedef void (APIENTRYP PFNGLLOADTRANSPOSEMATRIXFARBPROC) (const GLfloat *m);
typedef GLvoid *(APIENTRYP PFNGLMAPBUFFERARBPROC) (GLenum target, GLenum access);
typedef void (APIENTRYP PFNGLMULTTRANSPOSEMATRIXDARBPROC) (const GLdouble *m);
typedef void (APIENTRYP PFNGLMULTTRANSPOSEMATRIXFARBPROC) (const GLfloat *m);
typedef void (APIENTRYP PFNGLMULTIDRAWARRAYSEXTPROC) (GLenum mode, const GLint *first, const GLsizei *count, GLsizei drawcount);
typedef void (APIENTRYP PFNGLMULTIDRAWELEMENTSEXTPROC) (GLenum mode, const GLsizei *count, GLenum type, const GLvoid *const *indices, GLsizei drawcount);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFARBPROC) (GLenum pname, GLfloat param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFEXTPROC) (GLenum pname, GLfloat param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFVARBPROC) (GLenum pname, const GLfloat *params);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFVEXTPROC) (GLenum pname, const GLfloat *params);
typedef void (APIENTRYP PFNGLPRIORITIZETEXTURESEXTPROC) (GLsizei n, const GLuint *textures, const GLclampf *priorities);
typedef void (APIENTRYP PFNGLRENDERBUFFERSTORAGEEXTPROC) (GLenum target, GLenum internalformat, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLRENDERBUFFERSTORAGEMULTISAMPLEEXTPROC) (GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLSAMPLECOVERAGEARBPROC) (GLfloat value, GLboolean invert);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BEXTPROC) (GLbyte red, GLbyte green, GLbyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BVEXTPROC) (const GLbyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DEXTPROC) (GLdouble red, GLdouble green, GLdouble blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DVEXTPROC) (const GLdouble *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FEXTPROC) (GLfloat red, GLfloat green, GLfloat blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FVEXTPROC) (const GLfloat *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IEXTPROC) (GLint red, GLint green, GLint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IVEXTPROC) (const GLint *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SEXTPROC) (GLshort red, GLshort green, GLshort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SVEXTPROC) (const GLshort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBEXTPROC) (GLubyte red, GLubyte green, GLubyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBVEXTPROC) (const GLubyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIEXTPROC) (GLuint red, GLuint green, GLuint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIVEXTPROC) (const GLuint *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USEXTPROC) (GLushort red, GLushort green, GLushort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USVEXTPROC) (const GLushort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLORPOINTEREXTPROC) (GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
typedef void (APIENTRYP PFNGLTEXSUBIMAGE3DEXTPROC) (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const GLvoid *pixels);
typedef GLboolean (APIENTRYP PFNGLUNMAPBUFFERARBPROC) (GLenum target);

#ifdef GL_GLEXT_PROTOTYPES

/* Functions: src/ffi/multidraw.rs */
GLAPI void APIENTRY glMultiDrawArrays (GLenum mode, const GLint *first, const GLsizei *count, GLsizei drawcount);
GLAPI void APIENTRY glMultiDrawElements (GLenum mode, const GLsizei *count, GLenum type, const GLvoid *const *indices, GLsizei drawcount);

/* Functions: src/ffi/buffers.rs */
GLAPI void APIENTRY glGenBuffers (GLsizei n, GLuint *buffers);
GLAPI void APIENTRY glDeleteBuffers (GLsizei n, const GLuint *buffers);
GLAPI GLboolean APIENTRY glIsBuffer (GLuint buffer);
GLAPI void APIENTRY glBindBuffer (GLenum target, GLuint buffer);
GLAPI void APIENTRY glBufferData (GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage);
GLAPI void APIENTRY glBufferSubData (GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid *data);
GLAPI void APIENTRY glGetBufferSubData (GLenum target, GLintptr offset, GLsizeiptr size, GLvoid *data);
GLAPI GLvoid *APIENTRY glMapBuffer (GLenum target, GLenum access);
GLAPI GLboolean APIENTRY glUnmapBuffer (GLenum target);
GLAPI void APIENTRY glGetBufferParameteriv (GLenum target, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetBufferPointerv (GLenum target, GLenum pname, GLvoid **params);

/* Functions: src/ffi/fragment_ext.rs */
GLAPI void APIENTRY glBlendFuncSeparate (GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
GLAPI void APIENTRY glBlendEquationSeparate (GLenum modeRGB, GLenum modeAlpha);
GLAPI void APIENTRY glStencilFuncSeparate (GLenum face, GLenum func, GLint ref, GLuint mask);
GLAPI void APIENTRY glStencilOpSeparate (GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass);
GLAPI void APIENTRY glStencilMaskSeparate (GLenum face, GLuint mask);
GLAPI void APIENTRY glBlendFuncSeparateEXT (GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
GLAPI void APIENTRY glBlendEquationSeparateEXT (GLenum modeRGB, GLenum modeAlpha);
GLAPI void APIENTRY glBlendEquationEXT (GLenum mode);
GLAPI void APIENTRY glBlendColorEXT (GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha);

/* Functions: src/ffi/textures_ext.rs */
GLAPI void APIENTRY glGenerateMipmap (GLenum target);
GLAPI void APIENTRY glGenerateMipmapEXT (GLenum target);

/* Functions: src/ffi/framebuffers.rs */
GLAPI void APIENTRY glGenFramebuffers (GLsizei n, GLuint *framebuffers);
GLAPI void APIENTRY glDeleteFramebuffers (GLsizei n, const GLuint *framebuffers);
GLAPI void APIENTRY glBindFramebuffer (GLenum target, GLuint framebuffer);
GLAPI void APIENTRY glBindFramebufferEXT (GLenum target, GLuint framebuffer);
GLAPI GLboolean APIENTRY glIsFramebuffer (GLuint framebuffer);
GLAPI GLenum APIENTRY glCheckFramebufferStatus (GLenum target);
GLAPI void APIENTRY glFramebufferTexture1D (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
GLAPI void APIENTRY glFramebufferTexture2D (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
GLAPI void APIENTRY glFramebufferTexture3D (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level, GLint zoffset);
GLAPI void APIENTRY glFramebufferTextureLayer (GLenum target, GLenum attachment, GLuint texture, GLint level, GLint layer);
GLAPI void APIENTRY glFramebufferRenderbuffer (GLenum target, GLenum attachment, GLenum renderbuffertarget, GLuint renderbuffer);
GLAPI void APIENTRY glGenRenderbuffers (GLsizei n, GLuint *renderbuffers);
GLAPI void APIENTRY glDeleteRenderbuffers (GLsizei n, const GLuint *renderbuffers);
GLAPI void APIENTRY glBindRenderbuffer (GLenum target, GLuint renderbuffer);
GLAPI void APIENTRY glBindRenderbufferEXT (GLenum target, GLuint renderbuffer);
GLAPI GLboolean APIENTRY glIsRenderbuffer (GLuint renderbuffer);
GLAPI void APIENTRY glRenderbufferStorage (GLenum target, GLenum internalformat, GLsizei width, GLsizei height);
GLAPI void APIENTRY glRenderbufferStorageMultisample (GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height);
GLAPI void APIENTRY glGetRenderbufferParameteriv (GLenum target, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetFramebufferAttachmentParameteriv (GLenum target, GLenum attachment, GLenum pname, GLint *params);
GLAPI void APIENTRY glBlitFramebuffer (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);
GLAPI void APIENTRY glBlitFramebufferEXT (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter);

/* Functions: src/ffi/lighting_ext.rs */
GLAPI void APIENTRY glFogCoordf (GLfloat coord);
GLAPI void APIENTRY glFogCoordd (GLdouble coord);
GLAPI void APIENTRY glFogCoordfv (const GLfloat *coord);
GLAPI void APIENTRY glFogCoorddv (const GLdouble *coord);
GLAPI void APIENTRY glSecondaryColor3b (GLbyte red, GLbyte green, GLbyte blue);
GLAPI void APIENTRY glSecondaryColor3bv (const GLbyte *v);
GLAPI void APIENTRY glSecondaryColor3s (GLshort red, GLshort green, GLshort blue);
GLAPI void APIENTRY glSecondaryColor3sv (const GLshort *v);
GLAPI void APIENTRY glSecondaryColor3i (GLint red, GLint green, GLint blue);
GLAPI void APIENTRY glSecondaryColor3iv (const GLint *v);
GLAPI void APIENTRY glSecondaryColor3f (GLfloat red, GLfloat green, GLfloat blue);
GLAPI void APIENTRY glSecondaryColor3fv (const GLfloat *v);
GLAPI void APIENTRY glSecondaryColor3d (GLdouble red, GLdouble green, GLdouble blue);
GLAPI void APIENTRY glSecondaryColor3dv (const GLdouble *v);
GLAPI void APIENTRY glSecondaryColor3ub (GLubyte red, GLubyte green, GLubyte blue);
GLAPI void APIENTRY glSecondaryColor3ubv (const GLubyte *v);
GLAPI void APIENTRY glSecondaryColor3us (GLushort red, GLushort green, GLushort blue);
GLAPI void APIENTRY glSecondaryColor3usv (const GLushort *v);
GLAPI void APIENTRY glSecondaryColor3ui (GLuint red, GLuint green, GLuint blue);
GLAPI void APIENTRY glSecondaryColor3uiv (const GLuint *v);

/* Functions: src/ffi/arrays_gl14.rs */
GLAPI void APIENTRY glSecondaryColorPointer (GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
GLAPI void APIENTRY glFogCoordPointer (GLenum type, GLsizei stride, const GLvoid *pointer);

/* Functions: src/ffi/points.rs */
GLAPI void APIENTRY glPointParameterf (GLenum pname, GLfloat param);
GLAPI void APIENTRY glPointParameterfv (GLenum pname, const GLfloat *params);
GLAPI void APIENTRY glPointParameteri (GLenum pname, GLint param);
GLAPI void APIENTRY glPointParameteriv (GLenum pname, const GLint *params);

/* Functions: src/ffi/pixels_ext.rs */
GLAPI void APIENTRY glWindowPos2s (GLshort x, GLshort y);
GLAPI void APIENTRY glWindowPos2sv (const GLshort *v);
GLAPI void APIENTRY glWindowPos2i (GLint x, GLint y);
GLAPI void APIENTRY glWindowPos2iv (const GLint *v);
GLAPI void APIENTRY glWindowPos2f (GLfloat x, GLfloat y);
GLAPI void APIENTRY glWindowPos2fv (const GLfloat *v);
GLAPI void APIENTRY glWindowPos2d (GLdouble x, GLdouble y);
GLAPI void APIENTRY glWindowPos2dv (const GLdouble *v);
GLAPI void APIENTRY glWindowPos3s (GLshort x, GLshort y, GLshort z);
GLAPI void APIENTRY glWindowPos3sv (const GLshort *v);
GLAPI void APIENTRY glWindowPos3i (GLint x, GLint y, GLint z);
GLAPI void APIENTRY glWindowPos3iv (const GLint *v);
GLAPI void APIENTRY glWindowPos3f (GLfloat x, GLfloat y, GLfloat z);
GLAPI void APIENTRY glWindowPos3fv (const GLfloat *v);
GLAPI void APIENTRY glWindowPos3d (GLdouble x, GLdouble y, GLdouble z);
GLAPI void APIENTRY glWindowPos3dv (const GLdouble *v);
GLAPI void APIENTRY glWindowPos2sARB (GLshort x, GLshort y);
GLAPI void APIENTRY glWindowPos2svARB (const GLshort *v);
GLAPI void APIENTRY glWindowPos2iARB (GLint x, GLint y);
GLAPI void APIENTRY glWindowPos2ivARB (const GLint *v);
GLAPI void APIENTRY glWindowPos2fARB (GLfloat x, GLfloat y);
GLAPI void APIENTRY glWindowPos2fvARB (const GLfloat *v);
GLAPI void APIENTRY glWindowPos2dARB (GLdouble x, GLdouble y);
GLAPI void APIENTRY glWindowPos2dvARB (const GLdouble *v);
GLAPI void APIENTRY glWindowPos3sARB (GLshort x, GLshort y, GLshort z);
GLAPI void APIENTRY glWindowPos3svARB (const GLshort *v);
GLAPI void APIENTRY glWindowPos3iARB (GLint x, GLint y, GLint z);
GLAPI void APIENTRY glWindowPos3ivARB (const GLint *v);
GLAPI void APIENTRY glWindowPos3fARB (GLfloat x, GLfloat y, GLfloat z);
GLAPI void APIENTRY glWindowPos3fvARB (const GLfloat *v);
GLAPI void APIENTRY glWindowPos3dARB (GLdouble x, GLdouble y, GLdouble z);
GLAPI void APIENTRY glWindowPos3dvARB (const GLdouble *v);

/* Functions: src/ffi/queries.rs */
GLAPI void APIENTRY glGenQueries (GLsizei n, GLuint *ids);
GLAPI void APIENTRY glDeleteQueries (GLsizei n, const GLuint *ids);
GLAPI GLboolean APIENTRY glIsQuery (GLuint id);
GLAPI void APIENTRY glBeginQuery (GLenum target, GLuint id);
GLAPI void APIENTRY glEndQuery (GLenum target);
GLAPI void APIENTRY glGetQueryiv (GLenum target, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetQueryObjectiv (GLuint id, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetQueryObjectuiv (GLuint id, GLenum pname, GLuint *params);
GLAPI void APIENTRY glGenQueriesARB (GLsizei n, GLuint *ids);
GLAPI void APIENTRY glDeleteQueriesARB (GLsizei n, const GLuint *ids);
GLAPI GLboolean APIENTRY glIsQueryARB (GLuint id);
GLAPI void APIENTRY glBeginQueryARB (GLenum target, GLuint id);
GLAPI void APIENTRY glEndQueryARB (GLenum target);
GLAPI void APIENTRY glGetQueryivARB (GLenum target, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetQueryObjectivARB (GLuint id, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetQueryObjectuivARB (GLuint id, GLenum pname, GLuint *params);

/* Functions: src/ffi/arrays_ext.rs */
GLAPI void APIENTRY glIndexPointerEXT (GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
GLAPI void APIENTRY glVertexPointerEXT (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
GLAPI void APIENTRY glColorPointerEXT (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
GLAPI void APIENTRY glNormalPointerEXT (GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
GLAPI void APIENTRY glTexCoordPointerEXT (GLint size, GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr);
GLAPI void APIENTRY glEdgeFlagPointerEXT (GLsizei stride, GLsizei count, const GLboolean *ptr);

/* Functions: src/ffi/transform_ext.rs */
GLAPI void APIENTRY glClipControl (GLenum origin, GLenum depth);

/* Functions: src/ffi/aliases_ext.rs */
GLAPI void APIENTRY glArrayElementEXT (GLint i);
GLAPI void APIENTRY glBindBufferARB (GLenum target, GLuint buffer);
GLAPI void APIENTRY glBindTextureEXT (GLenum target, GLuint texture);
GLAPI void APIENTRY glBufferDataARB (GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage);
GLAPI void APIENTRY glBufferSubDataARB (GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid *data);
GLAPI GLenum APIENTRY glCheckFramebufferStatusEXT (GLenum target);
GLAPI void APIENTRY glCompressedTexImage1DARB (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLint border, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCompressedTexImage2DARB (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLint border, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCompressedTexImage3DARB (GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCompressedTexSubImage1DARB (GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCompressedTexSubImage2DARB (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCompressedTexSubImage3DARB (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLsizei image_size, const GLvoid *data);
GLAPI void APIENTRY glCopyTexSubImage3DEXT (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height);
GLAPI void APIENTRY glDeleteBuffersARB (GLsizei n, const GLuint *buffers);
GLAPI void APIENTRY glDeleteFramebuffersEXT (GLsizei n, const GLuint *framebuffers);
GLAPI void APIENTRY glDeleteRenderbuffersEXT (GLsizei n, const GLuint *renderbuffers);
GLAPI void APIENTRY glDrawArraysEXT (GLenum mode, GLint first, GLsizei count);
GLAPI void APIENTRY glDrawRangeElementsEXT (GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const GLvoid *indices);
GLAPI void APIENTRY glFogCoordPointerEXT (GLenum type, GLsizei stride, const GLvoid *pointer);
GLAPI void APIENTRY glFogCoorddEXT (GLdouble coord);
GLAPI void APIENTRY glFogCoorddvEXT (const GLdouble *coord);
GLAPI void APIENTRY glFogCoordfEXT (GLfloat coord);
GLAPI void APIENTRY glFogCoordfvEXT (const GLfloat *coord);
GLAPI void APIENTRY glFramebufferRenderbufferEXT (GLenum target, GLenum attachment, GLenum renderbuffertarget, GLuint renderbuffer);
GLAPI void APIENTRY glFramebufferTexture1DEXT (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
GLAPI void APIENTRY glFramebufferTexture2DEXT (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level);
GLAPI void APIENTRY glFramebufferTexture3DEXT (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level, GLint zoffset);
GLAPI void APIENTRY glFramebufferTextureLayerEXT (GLenum target, GLenum attachment, GLuint texture, GLint level, GLint layer);
GLAPI void APIENTRY glGenBuffersARB (GLsizei n, GLuint *buffers);
GLAPI void APIENTRY glGenFramebuffersEXT (GLsizei n, GLuint *framebuffers);
GLAPI void APIENTRY glGenRenderbuffersEXT (GLsizei n, GLuint *renderbuffers);
GLAPI void APIENTRY glGetBufferParameterivARB (GLenum target, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetBufferPointervARB (GLenum target, GLenum pname, GLvoid **params);
GLAPI void APIENTRY glGetBufferSubDataARB (GLenum target, GLintptr offset, GLsizeiptr size, GLvoid *data);
GLAPI void APIENTRY glGetCompressedTexImageARB (GLenum target, GLint level, GLvoid *img);
GLAPI void APIENTRY glGetFramebufferAttachmentParameterivEXT (GLenum target, GLenum attachment, GLenum pname, GLint *params);
GLAPI void APIENTRY glGetPointervEXT (GLenum pname, GLvoid **params);
GLAPI void APIENTRY glGetRenderbufferParameterivEXT (GLenum target, GLenum pname, GLint *params);
GLAPI GLboolean APIENTRY glIsBufferARB (GLuint buffer);
GLAPI GLboolean APIENTRY glIsFramebufferEXT (GLuint framebuffer);
GLAPI GLboolean APIENTRY glIsRenderbufferEXT (GLuint renderbuffer);
GLAPI void APIENTRY glLoadTransposeMatrixdARB (const GLdouble *m);
GLAPI void APIENTRY glLoadTransposeMatrixfARB (const GLfloat *m);
GLAPI GLvoid *APIENTRY glMapBufferARB (GLenum target, GLenum access);
GLAPI void APIENTRY glMultTransposeMatrixdARB (const GLdouble *m);
GLAPI void APIENTRY glMultTransposeMatrixfARB (const GLfloat *m);
GLAPI void APIENTRY glMultiDrawArraysEXT (GLenum mode, const GLint *first, const GLsizei *count, GLsizei drawcount);
GLAPI void APIENTRY glMultiDrawElementsEXT (GLenum mode, const GLsizei *count, GLenum type, const GLvoid *const *indices, GLsizei drawcount);
GLAPI void APIENTRY glPointParameterfARB (GLenum pname, GLfloat param);
GLAPI void APIENTRY glPointParameterfEXT (GLenum pname, GLfloat param);
GLAPI void APIENTRY glPointParameterfvARB (GLenum pname, const GLfloat *params);
GLAPI void APIENTRY glPointParameterfvEXT (GLenum pname, const GLfloat *params);
GLAPI void APIENTRY glPrioritizeTexturesEXT (GLsizei n, const GLuint *textures, const GLclampf *priorities);
GLAPI void APIENTRY glRenderbufferStorageEXT (GLenum target, GLenum internalformat, GLsizei width, GLsizei height);
GLAPI void APIENTRY glRenderbufferStorageMultisampleEXT (GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height);
GLAPI void APIENTRY glSampleCoverageARB (GLfloat value, GLboolean invert);
GLAPI void APIENTRY glSecondaryColor3bEXT (GLbyte red, GLbyte green, GLbyte blue);
GLAPI void APIENTRY glSecondaryColor3bvEXT (const GLbyte *v);
GLAPI void APIENTRY glSecondaryColor3dEXT (GLdouble red, GLdouble green, GLdouble blue);
GLAPI void APIENTRY glSecondaryColor3dvEXT (const GLdouble *v);
GLAPI void APIENTRY glSecondaryColor3fEXT (GLfloat red, GLfloat green, GLfloat blue);
GLAPI void APIENTRY glSecondaryColor3fvEXT (const GLfloat *v);
GLAPI void APIENTRY glSecondaryColor3iEXT (GLint red, GLint green, GLint blue);
GLAPI void APIENTRY glSecondaryColor3ivEXT (const GLint *v);
GLAPI void APIENTRY glSecondaryColor3sEXT (GLshort red, GLshort green, GLshort blue);
GLAPI void APIENTRY glSecondaryColor3svEXT (const GLshort *v);
GLAPI void APIENTRY glSecondaryColor3ubEXT (GLubyte red, GLubyte green, GLubyte blue);
GLAPI void APIENTRY glSecondaryColor3ubvEXT (const GLubyte *v);
GLAPI void APIENTRY glSecondaryColor3uiEXT (GLuint red, GLuint green, GLuint blue);
GLAPI void APIENTRY glSecondaryColor3uivEXT (const GLuint *v);
GLAPI void APIENTRY glSecondaryColor3usEXT (GLushort red, GLushort green, GLushort blue);
GLAPI void APIENTRY glSecondaryColor3usvEXT (const GLushort *v);
GLAPI void APIENTRY glSecondaryColorPointerEXT (GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
GLAPI void APIENTRY glTexSubImage3DEXT (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const GLvoid *pixels);
GLAPI GLboolean APIENTRY glUnmapBufferARB (GLenum target);

#endif /* GL_GLEXT_PROTOTYPES */

#ifdef __cplusplus
}
#endif

#endif /* __gl_glext_h_ */
