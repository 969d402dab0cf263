/* ibl_probes.c - chapter 19's probes on the GPU (ibl_probes.h). */
#include "ibl_probes.h"

#include "gl_program.h"
#include "gl_util.h"
#include "ibl_sh.h"
#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* The capture draws the scene as chapter 00 does: back faces culled, the nearest surface wins. */
static const gl_pass_state capture_pass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
static const gl_pass_state filter_pass = {.depth_write = false};

/* GL's cube faces: where each looks, and its up (negative y: a face's rows run down its t axis). */
static const float face_forward[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
static const float face_up[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

static GLuint cube_create(int size, int levels)
{
    GLuint t = gl_texture_create();
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    for (int l = 0; l < levels; l++)
        for (int f = 0; f < 6; f++)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, l, GL_RGBA16F, size >> l, size >> l, 0, GL_RGBA, GL_FLOAT,
                         NULL);
    gl_texture_sampling(GL_TEXTURE_CUBE_MAP, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return t;
}

/* The split-sum table, once: one full-screen pass (ibl_brdf.frag). */
static bool brdf_make(ibl *b)
{
    int n = b->desc.brdf_size;
    b->brdf = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D, b->brdf);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, n, n, 0, GL_RG, GL_FLOAT, NULL);
    gl_texture_sampling(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, b->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, b->brdf, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    glViewport(0, 0, n, n);
    gl_pass_state_apply(&filter_pass);
    glUseProgram(b->brdf_program);
    glUniform1f(glGetUniformLocation(b->brdf_program, "u_size"), (float)n);
    glUniform1i(glGetUniformLocation(b->brdf_program, "u_samples"), b->desc.brdf_samples);
    gl_draw_fullscreen();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_pass_state_reset();
    return gl_check("19 split-sum table");
}

bool ibl_probes_create(ibl *b, const ibl_desc *desc)
{
    b->desc = *desc;
    b->on = true;
    b->framebuffer = gl_framebuffer_create();
    b->depth = gl_renderbuffer_create();
    glBindRenderbuffer(GL_RENDERBUFFER, b->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, desc->size, desc->size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    /* filtered lookups across a cube's face edges, not clamped to each face (the seams) */
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    b->prefilter_program = gl_program_load("fullscreen.vert", "ibl_prefilter.frag", NULL);
    b->brdf_program = gl_program_load("fullscreen.vert", "ibl_brdf.frag", NULL);
    return b->prefilter_program && b->brdf_program && forward_create(&b->capture) && brdf_make(b);
}

/* Face f of probe p: the scene from its centre, 90 degrees square, in linear radiance; where
 * nothing is drawn, the scene's ambient radiance (the light from far away the constant stood for). */
static bool capture_face(ibl *b, const gpu_scene *gs, const ibl_probe *p, int f)
{
    gpu_scene view = *gs; /* the same meshes, objects and lights; another camera */
    frame_view *v = &view.view;
    float centre[3] = {p->sphere.position[0], p->sphere.position[1], p->sphere.position[2]};
    vec3 target = {centre[0] + face_forward[f][0], centre[1] + face_forward[f][1], centre[2] + face_forward[f][2]};
    float near_plane = 0.02f, far_plane = gs->src->camera.far_plane;
    vec3 up = {face_up[f][0], face_up[f][1], face_up[f][2]};
    glm_lookat(centre, target, up, v->view);
    glm_perspective(glm_rad(90.0f), 1.0f, near_plane, far_plane, v->proj);
    glm_mat4_mul(v->proj, v->view, v->view_proj);
    glm_mat4_inv(v->proj, v->inv_proj), glm_mat4_inv(v->view, v->inv_view), glm_mat4_inv(v->view_proj, v->inv_view_proj);
    glm_vec3_copy(centre, v->eye);
    v->width = v->height = b->desc.size, v->near_plane = near_plane, v->far_plane = far_plane;

    glBindFramebuffer(GL_FRAMEBUFFER, b->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, p->radiance, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, b->depth);
    glViewport(0, 0, b->desc.size, b->desc.size);
    gl_pass_state_apply(&capture_pass);
    const float *sky = gs->src->ambient;
    glClearColor(sky[0], sky[1], sky[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    bool ok = forward_draw_shaded(&b->capture, &view, (forward_options){.linear_output = true});
    gl_pass_state_reset();
    return ok;
}

/* The irradiance: level 0 of the capture read back, projected on bands 0-2 in double precision. */
static bool project_irradiance(ibl_probe *p, int size)
{
    float *faces[6] = {0};
    bool ok = true;
    glBindTexture(GL_TEXTURE_CUBE_MAP, p->radiance);
    for (int f = 0; f < 6 && ok; f++) {
        faces[f] = malloc(sizeof(float) * 3 * (size_t)size * (size_t)size);
        ok = faces[f] != NULL;
        if (ok)
            glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGB, GL_FLOAT, faces[f]);
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    if (ok) {
        double sh[SHADER_IBL_SH_COEFFS][3];
        ibl_sh_project((const float *const *)faces, size, sh);
        for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
            for (int c = 0; c < 3; c++)
                p->sh[k][c] = (float)sh[k][c];
    } else
        log_error("19: out of memory reading a probe back");
    for (int f = 0; f < 6; f++)
        free(faces[f]);
    return ok;
}

/* The prefiltered chain: level l of every face, roughness l / (levels - 1) (ibl_prefilter.frag). */
static bool prefilter(ibl *b, const ibl_probe *p)
{
    GLuint prog = b->prefilter_program;
    glBindFramebuffer(GL_FRAMEBUFFER, b->framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    gl_pass_state_apply(&filter_pass);
    glUseProgram(prog);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, p->radiance);
    glUniform1i(glGetUniformLocation(prog, "u_source"), SHADER_UNIT_IMAGE);
    glUniform1f(glGetUniformLocation(prog, "u_source_size"), (float)b->desc.size);
    glUniform1i(glGetUniformLocation(prog, "u_samples"), b->desc.samples);
    for (int l = 0; l < b->desc.levels; l++) {
        int size = b->desc.size >> l;
        glViewport(0, 0, size, size);
        glUniform1f(glGetUniformLocation(prog, "u_size"), (float)size);
        glUniform1f(glGetUniformLocation(prog, "u_roughness"), (float)l / (float)(b->desc.levels - 1));
        for (int f = 0; f < 6; f++) {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, p->specular, l);
            glUniform1i(glGetUniformLocation(prog, "u_face"), f);
            gl_draw_fullscreen();
        }
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_pass_state_reset();
    return gl_check("19 prefilter");
}

bool ibl_probes_capture(ibl *b, const gpu_scene *gs)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    const scene *s = gs->src;
    int levels_all = 1;
    while ((b->desc.size >> levels_all) > 0)
        levels_all++;
    for (; b->count < s->probe_count; b->count++) { /* the textures once; a capture again reuses them */
        b->probes[b->count].radiance = cube_create(b->desc.size, levels_all);
        b->probes[b->count].specular = cube_create(b->desc.size, b->desc.levels);
    }
    for (int i = 0; i < s->probe_count; i++) {
        ibl_probe *p = &b->probes[i];
        p->sphere = s->probes[i];
        bool ok = true;
        for (int f = 0; f < 6 && ok; f++)
            ok = capture_face(b, gs, p, f);
        glBindTexture(GL_TEXTURE_CUBE_MAP, p->radiance);
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP); /* for the prefilter's lookups by solid angle */
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        if (!ok || !project_irradiance(p, b->desc.size) || !prefilter(b, p))
            return false;
    }
    glFinish();
    clock_gettime(CLOCK_MONOTONIC, &t1);
    b->capture_ms = (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) * 1e-6;
    return gl_check("19 capture");
}

void ibl_probes_pick(ibl *b, const float eye[3])
{
    scene_probe spheres[SCENE_PROBE_MAX];
    for (int i = 0; i < b->count; i++)
        spheres[i] = b->probes[i].sphere;
    b->picked_count = ibl_probes_pick_indices(spheres, b->count, eye, b->picked);
}

void ibl_probes_bind(GLuint program, const void *ibl_state)
{
    const ibl *b = ibl_state;
    float spheres[SHADER_IBL_MAX_PICKED][4] = {{0}};
    float sh[SHADER_IBL_MAX_PICKED * SHADER_IBL_SH_COEFFS][3] = {{0}};
    for (int k = 0; k < SHADER_IBL_MAX_PICKED; k++) {
        /* every sampler gets a cube, the unused ones the first probe's (never read) */
        const ibl_probe *p = &b->probes[k < b->picked_count ? b->picked[k] : (b->picked_count ? b->picked[0] : 0)];
        glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IBL_PROBES + k);
        glBindTexture(GL_TEXTURE_CUBE_MAP, b->count ? p->specular : 0);
        char name[32];
        snprintf(name, sizeof name, "u_probe_specular%d", k);
        glUniform1i(glGetUniformLocation(program, name), SHADER_UNIT_IBL_PROBES + k);
        if (k >= b->picked_count)
            continue;
        glm_vec3_copy((float *)p->sphere.position, spheres[k]);
        spheres[k][3] = p->sphere.radius;
        for (int c = 0; c < SHADER_IBL_SH_COEFFS; c++)
            glm_vec3_copy((float *)p->sh[c], sh[k * SHADER_IBL_SH_COEFFS + c]);
    }
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IBL_BRDF);
    glBindTexture(GL_TEXTURE_2D, b->brdf);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_ibl_brdf"), SHADER_UNIT_IBL_BRDF);
    glUniform1i(glGetUniformLocation(program, "u_ibl_on"), b->on);
    glUniform1i(glGetUniformLocation(program, "u_probe_count"), b->picked_count);
    glUniform4fv(glGetUniformLocation(program, "u_probe_sphere"), SHADER_IBL_MAX_PICKED, &spheres[0][0]);
    glUniform3fv(glGetUniformLocation(program, "u_probe_sh"), SHADER_IBL_MAX_PICKED * SHADER_IBL_SH_COEFFS, &sh[0][0]);
    glUniform1f(glGetUniformLocation(program, "u_probe_lods"), (float)(b->desc.levels - 1));
}

long ibl_probes_bytes(const ibl *b)
{
    long face = (long)b->desc.size * b->desc.size * 8; /* RGBA16F */
    long radiance = 6 * face * 4 / 3, specular = 0;
    for (int l = 0; l < b->desc.levels; l++)
        specular += 6 * face >> (2 * l);
    return b->count * (radiance + specular) + (long)b->desc.brdf_size * b->desc.brdf_size * 4;
}

void ibl_probes_destroy(ibl *b)
{
    for (int i = 0; i < b->count; i++)
        gl_texture_destroy(&b->probes[i].radiance), gl_texture_destroy(&b->probes[i].specular);
    GLuint *const programs[] = {&b->prefilter_program, &b->brdf_program};
    for (int i = 0; i < 2; i++)
        gl_program_destroy(programs[i]);
    gl_texture_destroy(&b->brdf);
    gl_renderbuffer_destroy(&b->depth);
    gl_framebuffer_destroy(&b->framebuffer);
    forward_destroy(&b->capture);
    b->count = 0;
}
