/* gpu_textures.c - see gpu_textures.h. */
#include "gpu_textures.h"

#include "log.h"
#include "shader_layout.h"
#include "texture_data.h"

#include <stdlib.h>
#include <string.h>

/* GL 4.6 made anisotropic filtering core; before it, an extension under either name. */
static bool has_anisotropy(void)
{
    if (GLAD_GL_VERSION_4_6)
        return true;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; i++) {
        const char *name = (const char *)glGetStringi(GL_EXTENSIONS, (GLuint)i);
        if (name && (strcmp(name, "GL_ARB_texture_filter_anisotropic") == 0 ||
                     strcmp(name, "GL_EXT_texture_filter_anisotropic") == 0))
            return true;
    }
    return false;
}

/* One array: its layers' storage, each image resampled into its layer, then the mipmaps. */
static bool make_array(const scene *s, bool srgb, int side, int layers, const int *layer, float anisotropy,
                       GLuint *out)
{
    *out = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D_ARRAY, *out);
    GLenum format = srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, (GLint)format, side, side, layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    unsigned char *rgba = malloc((size_t)side * side * 4);
    bool ok = rgba != NULL;
    if (!ok)
        log_error("out of memory for a %dx%d texture layer", side, side);
    if (ok && layers == 1 && side == 1) { /* no image of this kind: white, so a stray read is harmless */
        memset(rgba, 255, 4);
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    }
    for (int i = 0; ok && i < s->texture_count; i++) {
        if (s->textures[i].srgb != srgb)
            continue;
        ok = texture_data_load(s, i, side, rgba);
        if (ok)
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, layer[i], side, side, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    }
    free(rgba);
    /* A 1x1 placeholder has nothing to filter: nearest, no mipmaps, no anisotropy. The shaders read
     * it in lanes whose result they discard (llvmpipe runs both sides of a branch), and llvmpipe's
     * anisotropic path took seconds a frame on it (the teapots at 800x800: 33 s against 0.2). */
    bool placeholder = layers == 1 && side == 1;
    if (!placeholder)
        glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    gl_texture_sampling(GL_TEXTURE_2D_ARRAY, placeholder ? GL_NEAREST : GL_LINEAR_MIPMAP_LINEAR,
                        placeholder ? GL_NEAREST : GL_LINEAR, GL_REPEAT);
    if (anisotropy > 1.0f && !placeholder)
        glTexParameterf(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    return ok && gl_check("gpu_textures: an array");
}

static float anisotropy_wanted = GPU_TEXTURES_ANISOTROPY;

void gpu_textures_set_anisotropy(float most) { anisotropy_wanted = most >= 1.0f ? most : 1.0f; }

bool gpu_textures_create(const scene *s, gpu_textures *out)
{
    memset(out, 0, sizeof *out);
    out->layer = calloc((size_t)s->texture_count + 1, sizeof *out->layer);
    if (!out->layer) {
        log_error("out of memory for %d textures", s->texture_count);
        return false;
    }
    for (int i = 0; i < s->texture_count; i++)
        out->layer[i] = s->textures[i].srgb ? out->srgb_layers++ : out->linear_layers++;
    GLint max_side = 0, max_layers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
    if (out->srgb_layers > max_layers || out->linear_layers > max_layers) {
        log_error("%d images of one colour space: more than this context's %d array layers",
                  out->srgb_layers > out->linear_layers ? out->srgb_layers : out->linear_layers, max_layers);
        gpu_textures_destroy(out);
        return false;
    }
    int cap = max_side < GPU_TEXTURES_SIDE_MAX ? max_side : GPU_TEXTURES_SIDE_MAX;
    out->srgb_side = texture_data_layer_size(s, true, cap);
    out->linear_side = texture_data_layer_size(s, false, cap);
    if ((out->srgb_layers && !out->srgb_side) || (out->linear_layers && !out->linear_side)) {
        gpu_textures_destroy(out); /* an image that cannot be read: logged */
        return false;
    }
    out->anisotropy = 1.0f;
    if (anisotropy_wanted > 1.0f && has_anisotropy()) {
        GLfloat most = 1.0f;
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
        out->anisotropy = most < anisotropy_wanted ? most : anisotropy_wanted;
    }
    bool ok = make_array(s, true, out->srgb_layers ? out->srgb_side : 1, out->srgb_layers ? out->srgb_layers : 1,
                         out->layer, out->anisotropy, &out->srgb) &&
              make_array(s, false, out->linear_layers ? out->linear_side : 1,
                         out->linear_layers ? out->linear_layers : 1, out->layer, out->anisotropy, &out->linear);
    if (!ok)
        gpu_textures_destroy(out);
    return ok;
}

void gpu_textures_destroy(gpu_textures *t)
{
    gl_texture_destroy(&t->srgb);
    gl_texture_destroy(&t->linear);
    free(t->layer);
    memset(t, 0, sizeof *t);
}

void gpu_textures_bind(const gpu_textures *t, GLuint program)
{
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_MAPS_SRGB);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t->srgb);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_MAPS_LINEAR);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t->linear);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_maps_srgb"), SHADER_UNIT_MAPS_SRGB);
    glUniform1i(glGetUniformLocation(program, "u_maps_linear"), SHADER_UNIT_MAPS_LINEAR);
}
