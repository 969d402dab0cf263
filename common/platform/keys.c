/* keys.c - see keys.h. */
#include "keys.h"

#include <ctype.h>
#include <string.h>

static const key_binding table[] = {
    {KEY_MOUSE, "left drag", NULL, KEY_ACTION_MOUSE, "orbit around the target (on the split's divider: move it)"},
    {KEY_MOUSE, "right drag", NULL, KEY_ACTION_MOUSE, "look around (fly)"},
    {KEY_MOUSE, "scroll", NULL, KEY_ACTION_MOUSE, "zoom towards the target"},
    {'W', "W", NULL, KEY_ACTION_FLY, "fly forward (held; A S D: left, back, right)"},
    {'A', "A", NULL, KEY_ACTION_FLY, "fly left (held)"},
    {'S', "S", NULL, KEY_ACTION_FLY, "fly back (held)"},
    {'D', "D", NULL, KEY_ACTION_FLY, "fly right (held)"},
    {'F', "F", NULL, KEY_ACTION_FRAME_SCENE, "frame the whole scene"},
    {KEY_HOME, "Home", NULL, KEY_ACTION_HOME_CAMERA, "back to the scene's camera"},
    {'C', "C", NULL, KEY_ACTION_PRINT_POSE, "print the camera as a scene-file line (and for --camera)"},
    {'G', "G", NULL, KEY_ACTION_ADD_LIGHT, "add a light in front of the camera"},
    {'=', "+", NULL, KEY_ACTION_LIGHTS_DOUBLE, "double the generated lights (as --lights)"},
    {'-', "-", NULL, KEY_ACTION_LIGHTS_HALF, "halve the generated lights"},
    {KEY_BACKSPACE, "Backspace", NULL, KEY_ACTION_LIGHTS_RESTORE, "the lights the run started with again (after G, + and -)"},
    {'R', "R", NULL, KEY_ACTION_RENDERER, "next renderer (--renderer lists them; every chapter has forward and Forward+)"},
    {'V', "V", NULL, KEY_ACTION_VIEW, "next view (--view lists them: G-buffer targets, debug views)"},
    {'M', "M", NULL, KEY_ACTION_COMPARE, "compare with forward: split screen, difference (beyond 1/255, as a heat map), off"},
    {',', ",", NULL, KEY_ACTION_DIVIDER_LEFT, "move the split's divider left (or drag it)"},
    {'.', ".", NULL, KEY_ACTION_DIVIDER_RIGHT, "move the split's divider right"},
    {'[', "[", NULL, KEY_ACTION_CUTOFF_HALF, "halve the attenuation cut-off"},
    {']', "]", NULL, KEY_ACTION_CUTOFF_DOUBLE, "double the attenuation cut-off"},
    {'0', "0", NULL, KEY_ACTION_CUTOFF_EXACT, "the exact picture (no cut-off), or back"},
    {KEY_SPACE, "Space", NULL, KEY_ACTION_PAUSE, "pause / resume the animation"},
    {'H', "H", NULL, KEY_ACTION_OVERLAY, "on-screen overlay: what is drawn and what it costs"},
    {KEY_F1, "F1", NULL, KEY_ACTION_KEY_LIST, "list these keys on screen"},
    {'P', "P", NULL, KEY_ACTION_SCREENSHOT, "save the picture (the comparison too, never the overlay) into out/"},
    {KEY_ESCAPE, "Esc", NULL, KEY_ACTION_QUIT, "quit"},
    {'Q', "Q", NULL, KEY_ACTION_QUIT, "quit"},
    {'I', "I", "04", KEY_ACTION_CHAPTER, "scale the volume mesh by 1 / inradius, or not"},
    {'B', "B", "06", KEY_ACTION_CHAPTER, "accumulation buffer: rgba16f, rgba8 (saturates), rgba32f"},
    {'T', "T", "06", KEY_ACTION_CHAPTER, "tone map: none, exposure, reinhard"},
    {KEY_PAGE_DOWN, "PgDn", "06", KEY_ACTION_CHAPTER, "halve the exposure"},
    {KEY_PAGE_UP, "PgUp", "06", KEY_ACTION_CHAPTER, "double the exposure"},
    {'X', "X", "07", KEY_ACTION_CHAPTER, "cull front faces (right), back faces, or none (both wrong)"},
    {'Z', "Z", "07", KEY_ACTION_CHAPTER, "depth clamp on / off"},
    {'B', "B", "08", KEY_ACTION_CHAPTER, "batches of lights whose rectangles do not overlap, or one light per pass"},
    {'X', "X", "08", KEY_ACTION_CHAPTER, "count where the depth test fails (right) or passes (wrong inside a volume)"},
    {'Z', "Z", "08", KEY_ACTION_CHAPTER, "depth clamp on / off"},
    {'L', "L", "10", KEY_ACTION_CHAPTER, "tile lists made by the compute shader or on the CPU (as --path; same picture)"},
    {'L', "L", "11", KEY_ACTION_CHAPTER, "light lists made by compute shaders or on the CPU (as --assign; same picture)"},
    {'O', "O", "12", KEY_ACTION_CHAPTER, "glass order: back to front, or the scene's (wrong)"},
    {'K', "K", "14", KEY_ACTION_CHAPTER, "shadows on / off (off: every light unshadowed, chapter 11's picture)"},
    {'B', "B", "15", KEY_ACTION_CHAPTER, "light buffer's specular: rgb (two targets, forward's picture) or mono (one channel)"},
    {'K', "K", "15", KEY_ACTION_CHAPTER, "shadows on / off (started with --shadows N: chapter 14's atlas)"},
    {'K', "K", "16", KEY_ACTION_CHAPTER, "shadows on / off (started with --shadows N: chapter 14's atlas)"},
    {'O', "O", "17", KEY_ACTION_CHAPTER, "ambient occlusion on / off (off: chapter 11's picture)"},
    {'K', "K", "17", KEY_ACTION_CHAPTER, "shadows on / off (started with --shadows N: chapter 14's atlas)"},
    {'T', "T", "17", KEY_ACTION_CHAPTER, "halve the occlusion's radius (as --ao-radius)"},
    {'Y', "Y", "17", KEY_ACTION_CHAPTER, "double the occlusion's radius"},
    {'J', "J", "17", KEY_ACTION_CHAPTER, "halve the occlusion's directions (as --ao-samples)"},
    {'L', "L", "17", KEY_ACTION_CHAPTER, "double the occlusion's directions (64 at most)"},
    {'B', "B", "17", KEY_ACTION_CHAPTER, "a smaller occlusion blur window (as --ao-blur; 0: none)"},
    {'N', "N", "17", KEY_ACTION_CHAPTER, "a larger occlusion blur window (16 at most)"},
    {'1', "1-8", "18", KEY_ACTION_CHAPTER, "view: lit, albedo, metallic, roughness, normal, occlusion, depth, emissive (as --view)"},
    {'-', "-", "18", KEY_ACTION_CHAPTER, "halve the exposure (chapter 18 takes - and + from the generated lights)"},
    {'=', "+", "18", KEY_ACTION_CHAPTER, "double the exposure"},
    {'T', "T", "18", KEY_ACTION_CHAPTER, "halve the ambient light"},
    {'Y', "Y", "18", KEY_ACTION_CHAPTER, "double the ambient light"},
    {'I', "IJKL", "18", KEY_ACTION_CHAPTER, "move every light together: away, left, nearer, right (-z, -x, +z, +x)"},
    {KEY_UP, "Up", "18", KEY_ACTION_CHAPTER, "move every light together up"},
    {KEY_DOWN, "Down", "18", KEY_ACTION_CHAPTER, "move every light together down"},
    {'N', "N", "18", KEY_ACTION_CHAPTER, "shadows on / off (started with --shadows N; K moves the lights here)"},
    {'I', "I", "19", KEY_ACTION_CHAPTER, "image-based light from the probes on / off (off: chapter 11's picture)"},
    {'U', "U", "19", KEY_ACTION_CHAPTER, "capture every probe again (after the lights moved)"},
    {'O', "O", "19", KEY_ACTION_CHAPTER, "chapter 17's ambient occlusion on / off, on the probes' light too (as --ssao)"},
    {'K', "K", "19", KEY_ACTION_CHAPTER, "shadows on / off (started with --shadows N: chapter 14's atlas)"},
    {'T', "T", "19", KEY_ACTION_CHAPTER, "halve the occlusion's radius (as --ao-radius)"},
    {'Y', "Y", "19", KEY_ACTION_CHAPTER, "double the occlusion's radius"},
    {'J', "J", "19", KEY_ACTION_CHAPTER, "halve the occlusion's directions (as --ao-samples)"},
    {'L', "L", "19", KEY_ACTION_CHAPTER, "double the occlusion's directions (64 at most)"},
    {'B', "B", "19", KEY_ACTION_CHAPTER, "a smaller occlusion blur window (as --ao-blur; 0: none)"},
    {'N', "N", "19", KEY_ACTION_CHAPTER, "a larger occlusion blur window (16 at most)"},
};

#define TABLE_SIZE (sizeof table / sizeof table[0])

/* A chapter binding applies in the program whose name starts with its number. */
static bool applies(const key_binding *b, const char *program)
{
    return !b->chapters || (program && strncmp(program, b->chapters, strlen(b->chapters)) == 0);
}

/* A row that stands for a group of keys ("1-8", "IJKL") also matches its others. */
static bool matches(const key_binding *b, int code)
{
    if (b->code == code)
        return true;
    if (strcmp(b->label, "1-8") == 0)
        return code >= '1' && code <= '8';
    return strcmp(b->label, "IJKL") == 0 && (code == 'J' || code == 'K' || code == 'L');
}

/* A chapter's own binding wins over the shared one of the same key (chapter 18's - and +). */
static const key_binding *find(int code, const char *program, bool chapter_only)
{
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (code != KEY_MOUSE && matches(&table[i], code) && applies(&table[i], program) &&
            (!chapter_only || table[i].chapters))
            return &table[i];
    return NULL;
}

const key_binding *keys_find(int code, const char *program)
{
    const key_binding *own = find(code, program, true);
    return own ? own : find(code, program, false);
}

void keys_print_help(FILE *stream, const char *program, bool views)
{
    fprintf(stream, "\nwindow keys:\n");
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (applies(&table[i], program) && (views || table[i].action != KEY_ACTION_VIEW) &&
            (table[i].code == KEY_MOUSE || keys_find(table[i].code, program) == &table[i])) /* not taken over */
            fprintf(stream, "  %-10s %s\n", table[i].label, table[i].does);
}

void keys_print_markdown(FILE *stream)
{
    fprintf(stream, "| key | chapter | does |\n|---|---|---|\n");
    for (size_t i = 0; i < TABLE_SIZE; i++)
        fprintf(stream, "| `%s` | %s | %s |\n", table[i].label, table[i].chapters ? table[i].chapters : "all",
                table[i].does);
}

int keys_code(const char *label)
{
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (table[i].code != KEY_MOUSE && strcmp(table[i].label, label) == 0)
            return table[i].code;
    if (label[0] && !label[1] && isgraph((unsigned char)label[0]))
        return toupper((unsigned char)label[0]);
    return 0;
}
