/* probe_readback.c - see probe_readback.h. */
#include "probe_readback.h"

#include "gl_util.h"

#include <stdlib.h>
#include <string.h>

static bool level_read(GLuint cube, int level, int size, cube_level *out)
{
    out->size = size;
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    for (int f = 0; f < 6; f++) {
        out->faces[f] = malloc(sizeof(float) * 4 * (size_t)size * (size_t)size);
        if (!out->faces[f])
            return false;
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, level, GL_RGBA, GL_FLOAT, out->faces[f]);
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return gl_check("read a cube level");
}

bool probe_readback(const ibl *b, int index, split_sum_probe *out)
{
    const ibl_probe *p = &b->probes[index];
    int n = b->desc.brdf_size;
    memset(out, 0, sizeof *out);
    out->table_size = n;
    out->table = malloc(sizeof(float) * 2 * (size_t)n * (size_t)n);
    bool ok = out->table && b->desc.levels <= SPLIT_SUM_MAX_LEVELS &&
              level_read(p->radiance, 0, b->desc.size, &out->radiance);
    out->level_count = b->desc.levels;
    for (int l = 0; ok && l < b->desc.levels; l++)
        ok = level_read(p->specular, l, b->desc.size >> l, &out->levels[l]);
    if (ok) {
        glBindTexture(GL_TEXTURE_2D, b->brdf);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, out->table);
        glBindTexture(GL_TEXTURE_2D, 0);
        ok = gl_check("read the split-sum table");
    }
    return ok;
}

static void level_free(cube_level *c)
{
    for (int f = 0; f < 6; f++)
        free(c->faces[f]), c->faces[f] = NULL;
}

void probe_readback_free(split_sum_probe *p)
{
    level_free(&p->radiance);
    for (int l = 0; l < SPLIT_SUM_MAX_LEVELS; l++)
        level_free(&p->levels[l]);
    free(p->table);
    memset(p, 0, sizeof *p);
}
