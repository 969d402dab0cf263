/* vis_meshes.c - see vis_meshes.h. */
#include "vis_meshes.h"

#include "log.h"

#include <stdlib.h>

static GLint buffer_size(GLuint buffer)
{
    GLint size = 0;
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
    return size;
}

/* One buffer holding every mesh's vertex buffer (or index buffer) back to back; firsts[m]: where mesh m's
 * begins, in bytes. */
static void concatenate(const gpu_scene *gs, bool indices, GLuint buffer, GLuint texture, GLenum format,
                        GLint *firsts)
{
    GLint total = 0;
    for (int m = 0; m < gs->src->mesh_count; m++) {
        firsts[m] = total;
        total += buffer_size(indices ? gs->meshes[m].ibo : gs->meshes[m].vbo);
    }
    gl_texture_buffer_upload(buffer, texture, format, NULL, (size_t)total);
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
    for (int m = 0; m < gs->src->mesh_count; m++) {
        GLuint from = indices ? gs->meshes[m].ibo : gs->meshes[m].vbo;
        glBindBuffer(GL_COPY_READ_BUFFER, from);
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, firsts[m], buffer_size(from));
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

bool vis_meshes_create(vis_meshes *vm, const gpu_scene *gs)
{
    const int meshes = gs->src->mesh_count, objects = gs->src->object_count;
    GLint *vertex_bytes = calloc((size_t)meshes + 1, sizeof *vertex_bytes);
    GLint *index_bytes = calloc((size_t)meshes + 1, sizeof *index_bytes);
    GLint *table = calloc(2 * (size_t)objects + 2, sizeof *table);
    bool ok = vertex_bytes && index_bytes && table;
    if (ok) {
        for (int i = 0; i < VIS_TABLES; i++)
            vm->buffer[i] = gl_buffer_create(), vm->texture[i] = gl_texture_create();
        concatenate(gs, false, vm->buffer[VIS_VERTICES], vm->texture[VIS_VERTICES], GL_R32F, vertex_bytes);
        concatenate(gs, true, vm->buffer[VIS_INDICES], vm->texture[VIS_INDICES], GL_R32UI, index_bytes);
        for (int o = 0; o < objects; o++) { /* bytes to entries: indices, then vertices */
            int m = gs->src->objects[o].mesh;
            table[2 * o] = index_bytes[m] / (GLint)sizeof(GLuint);
            table[2 * o + 1] = vertex_bytes[m] / (GLint)(MESH_VERTEX_FLOATS * sizeof(float));
        }
        gl_texture_buffer_upload(vm->buffer[VIS_OBJECTS], vm->texture[VIS_OBJECTS], GL_RG32I, table,
                                 (2 * (size_t)objects + 2) * sizeof *table);
    } else {
        log_error("16: out of memory for %d meshes' tables", meshes);
    }
    free(vertex_bytes);
    free(index_bytes);
    free(table);
    return ok && gl_check("16 triangle buffers");
}

void vis_meshes_destroy(vis_meshes *vm)
{
    for (int i = 0; i < VIS_TABLES; i++) {
        gl_texture_destroy(&vm->texture[i]);
        gl_buffer_destroy(&vm->buffer[i]);
    }
}

void vis_meshes_bind(const vis_meshes *vm, GLuint program, int unit)
{
    static const char *const names[VIS_TABLES] = {"u_vertices", "u_indices", "u_object_meshes"};
    for (int i = 0; i < VIS_TABLES; i++)
        gl_texture_buffer_bind(program, names[i], unit + i, vm->texture[i]);
}
