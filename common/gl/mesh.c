/* mesh.c - see mesh.h. */
#include "mesh.h"

#include "gl_util.h"

#include <string.h>

bool mesh_create(const mesh_data *data, mesh *out)
{
    memset(out, 0, sizeof *out);
    out->vao = gl_vertex_array_create();
    out->vbo = gl_buffer_create();
    out->ibo = gl_buffer_create();
    glBindVertexArray(out->vao);
    glBindBuffer(GL_ARRAY_BUFFER, out->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)data->vertex_count * MESH_VERTEX_FLOATS * (GLsizeiptr)sizeof(float),
                 data->vertices, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out->ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)data->index_count * (GLsizeiptr)sizeof(uint32_t),
                 data->indices, GL_STATIC_DRAW);
    const GLsizei stride = MESH_VERTEX_FLOATS * sizeof(float);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (const void *)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (const void *)(MESH_VERTEX_NORMAL * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, (const void *)(MESH_VERTEX_UV * sizeof(float)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, (const void *)(MESH_VERTEX_TANGENT * sizeof(float)));
    glBindVertexArray(0);
    out->index_count = data->index_count;
    memcpy(out->bounds_min, data->bounds_min, sizeof out->bounds_min);
    memcpy(out->bounds_max, data->bounds_max, sizeof out->bounds_max);
    out->bound_radius = data->bound_radius;
    return gl_check("mesh_create");
}

void mesh_destroy(mesh *m)
{
    gl_vertex_array_destroy(&m->vao);
    gl_buffer_destroy(&m->vbo);
    gl_buffer_destroy(&m->ibo);
}

void mesh_draw(const mesh *m)
{
    glBindVertexArray(m->vao);
    gl_draw_hooks_begin(false);
    glDrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT, 0);
    gl_draw_hooks_end();
}

void mesh_draw_instanced(const mesh *m, int instances)
{
    glBindVertexArray(m->vao);
    gl_draw_hooks_begin(false); /* nothing unless the benchmark counts bytes (draw_count.h) */
    glDrawElementsInstanced(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT, 0, instances);
    gl_draw_hooks_end();
}
