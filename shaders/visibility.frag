#version 330 core
// visibility.frag - chapter 16's visibility pass: each pixel keeps only WHICH triangle it sees, the
// object (+1, so that 0 is the background) above SHADER_VIS_TRIANGLE_BITS bits of the triangle's
// index in its mesh. gl_PrimitiveID counts the draw's triangles and starts again at 0 for each
// instance, so with forward.vert's instanced draws it is the index in the object's own mesh.
flat in int v_object;

layout(location = 0) out uint o_id;

void main()
{
    o_id = (uint(v_object + 1) << SHADER_VIS_TRIANGLE_BITS) | uint(gl_PrimitiveID);
}
