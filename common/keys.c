/* keys.c - see keys.h. */
#include "keys.h"

#include <string.h>

static const key_binding table[] = {
    {'R', "R", NULL, KEY_ACTION_RENDERER, "next renderer (--renderer lists them; every chapter has forward)"},
    {'V', "V", NULL, KEY_ACTION_VIEW, "next view (--view lists them: G-buffer targets, reach, ring, overdraw)"},
    {'[', "[", NULL, KEY_ACTION_CUTOFF_HALF, "halve the attenuation cut-off"},
    {']', "]", NULL, KEY_ACTION_CUTOFF_DOUBLE, "double the attenuation cut-off"},
    {'0', "0", NULL, KEY_ACTION_CUTOFF_EXACT, "the exact picture (no cut-off), or back"},
    {KEY_SPACE, "Space", NULL, KEY_ACTION_PAUSE, "pause / resume the animation"},
    {'P', "P", NULL, KEY_ACTION_SCREENSHOT, "save a screenshot into out/"},
    {KEY_ESCAPE, "Esc", NULL, KEY_ACTION_QUIT, "quit"},
    {'Q', "Q", NULL, KEY_ACTION_QUIT, "quit"},
    {'S', "S", "04", KEY_ACTION_CHAPTER, "scale the volume mesh by 1 / inradius, or not"},
    {'A', "A", "06", KEY_ACTION_CHAPTER, "accumulation buffer: rgba16f, rgba8 (saturates), rgba32f"},
    {'T', "T", "06", KEY_ACTION_CHAPTER, "tone map: none, exposure, reinhard"},
    {'-', "-", "06", KEY_ACTION_CHAPTER, "halve the exposure"},
    {'=', "=", "06", KEY_ACTION_CHAPTER, "double the exposure"},
    {'C', "C", "07", KEY_ACTION_CHAPTER, "cull front faces (right), back faces, or none (both wrong)"},
    {'D', "D", "07", KEY_ACTION_CHAPTER, "depth clamp on / off"},
};

#define TABLE_SIZE (sizeof table / sizeof table[0])

/* A chapter binding applies in the program whose name starts with its number. */
static bool applies(const key_binding *b, const char *program)
{
    return !b->chapters || (program && strncmp(program, b->chapters, strlen(b->chapters)) == 0);
}

const key_binding *keys_find(int code, const char *program)
{
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (table[i].code == code && applies(&table[i], program))
            return &table[i];
    return NULL;
}

void keys_print_help(FILE *stream, const char *program, bool views)
{
    fprintf(stream, "\nwindow keys:\n");
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (applies(&table[i], program) && (views || table[i].action != KEY_ACTION_VIEW))
            fprintf(stream, "  %-8s %s\n", table[i].label, table[i].does);
}

void keys_print_markdown(FILE *stream)
{
    fprintf(stream, "| key | chapter | does |\n|---|---|---|\n");
    for (size_t i = 0; i < TABLE_SIZE; i++)
        fprintf(stream, "| `%s` | %s | %s |\n", table[i].label, table[i].chapters ? table[i].chapters : "all",
                table[i].does);
}
