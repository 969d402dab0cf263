#version 330 core
// visibility.frag - chapter 16's visibility pass: each pixel keeps only WHICH triangle it sees, the
// object (+1, so that 0 is the background) above SHADER_VIS_TRIANGLE_BITS bits of the triangle's
// index in its mesh. gl_PrimitiveID counts the draw's triangles and starts again at 0 for each
// instance, so with forward.vert's instanced draws it is the index in the object's own mesh.
flat in int v_object;

layout(location = 0) out uint o_id;

void main()
{
#ifdef VIS_NO_PRIMITIVE_ID
    // chapter 16's --vis-pass no-primitive-id and depth-only: every pixel of an object its first
    // triangle, a wrong picture that times the pass without gl_PrimitiveID
    o_id = uint(v_object + 1) << SHADER_VIS_TRIANGLE_BITS;
#else
    o_id = (uint(v_object + 1) << SHADER_VIS_TRIANGLE_BITS) | uint(gl_PrimitiveID);
#endif
}
