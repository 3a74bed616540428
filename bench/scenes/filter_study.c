/*
 * filter_study.c - the checkerboard ground plane for the filter study (not part of the main benchmark).
 *
 * Run only by `bench --filter-study` (bench/README.md, bench/filter_study.md):
 * the ground plane of c_tests/tex_truth_plane.h (a 512x512 black/white
 * checkerboard with its untinted hand-made mip chain) with the filter named
 * by the environment variable FILTER_STUDY: nearest, linear,
 * nearest_mipmap_nearest, linear_mipmap_nearest, nearest_mipmap_linear,
 * linear_mipmap_linear (the default), or aniso2, aniso4, aniso8, aniso16
 * (LINEAR_MIPMAP_LINEAR with that GL_TEXTURE_MAX_ANISOTROPY_EXT). The
 * magnification filter is NEAREST for the NEAREST* minification filters and
 * LINEAR otherwise. The runner judges the last frame against the analytic
 * ground truth (bench/runner/ground_truth.rs).
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"
#include "../../c_tests/common.h"
#include "../../c_tests/tex_common.h"
#include "../../c_tests/tex_truth_plane.h"

static void scene_setup(int w, int h)
{
    static const struct {
        const char *name;
        GLenum min, mag;
        float aniso;
    } modes[] = {
        {"nearest", GL_NEAREST, GL_NEAREST, 1.0f},
        {"linear", GL_LINEAR, GL_LINEAR, 1.0f},
        {"nearest_mipmap_nearest", GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 1.0f},
        {"linear_mipmap_nearest", GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 1.0f},
        {"nearest_mipmap_linear", GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, 1.0f},
        {"linear_mipmap_linear", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0f},
        {"aniso2", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 2.0f},
        {"aniso4", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 4.0f},
        {"aniso8", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 8.0f},
        {"aniso16", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16.0f},
    };
    const char *want = getenv("FILTER_STUDY");
    size_t i, n = sizeof modes / sizeof modes[0];
    BENCH_UNUSED(w, h);
    if (!want || !*want)
        want = "linear_mipmap_linear";
    for (i = 0; i < n && strcmp(modes[i].name, want) != 0; i++)
        ;
    if (i == n) {
        fprintf(stderr, "FILTER_STUDY: unknown filter %s\n", want);
        exit(2);
    }
    sgl_truth_texture();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)modes[i].min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)modes[i].mag);
    if (modes[i].aniso > 1.0f)
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, modes[i].aniso);
    glEnable(GL_DEPTH_TEST);
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error in setup\n");
        exit(2);
    }
}

static void scene_frame(int w, int h)
{
    sgl_truth_draw(w, h);
}
