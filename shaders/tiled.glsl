// tiled.glsl - chapter 10's two numbers. chapters/10_tiled_deferred.c and common/renderers.c pass
// them as defines (TILED_DEFINES, from their own constants); these are the same values, for a shader
// compiled without them (tests/robust/run_glslang.sh, tests/run_tiled_glslang.sh).
#ifndef TILED_GLSL
#define TILED_GLSL
#ifndef TILE_SIZE
#define TILE_SIZE 16 // pixels per tile side
#endif
#ifndef VIEW_TILES
#define VIEW_TILES 3 // u_view_mode of the tiles view, beside SHADER_VIEW_*
#endif
#endif
