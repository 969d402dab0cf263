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
        vm->vertex_buffer = gl_buffer_create(), vm->vertex_texture = gl_texture_create();
        vm->index_buffer = gl_buffer_create(), vm->index_texture = gl_texture_create();
        vm->object_buffer = gl_buffer_create(), vm->object_texture = gl_texture_create();
        concatenate(gs, false, vm->vertex_buffer, vm->vertex_texture, GL_R32F, vertex_bytes);
        concatenate(gs, true, vm->index_buffer, vm->index_texture, GL_R32UI, index_bytes);
        for (int o = 0; o < objects; o++) { /* bytes to entries: indices, then vertices */
            int m = gs->src->objects[o].mesh;
            table[2 * o] = index_bytes[m] / (GLint)sizeof(GLuint);
            table[2 * o + 1] = vertex_bytes[m] / (GLint)(MESH_VERTEX_FLOATS * sizeof(float));
        }
        gl_texture_buffer_upload(vm->object_buffer, vm->object_texture, GL_RG32I, table,
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
    gl_texture_destroy(&vm->object_texture);
    gl_buffer_destroy(&vm->object_buffer);
    gl_texture_destroy(&vm->index_texture);
    gl_buffer_destroy(&vm->index_buffer);
    gl_texture_destroy(&vm->vertex_texture);
    gl_buffer_destroy(&vm->vertex_buffer);
}

void vis_meshes_bind(const vis_meshes *vm, GLuint program, int unit)
{
    gl_texture_buffer_bind(program, "u_vertices", unit, vm->vertex_texture);
    gl_texture_buffer_bind(program, "u_indices", unit + 1, vm->index_texture);
    gl_texture_buffer_bind(program, "u_object_meshes", unit + 2, vm->object_texture);
}
