/* fuzz_script.c - libFuzzer target for the --script parser (input_script_parse).
 *
 *   LLVMFuzzerTestOneInput(data, size)   parse the bytes as a script; on success, check the
 *                                        promises input_script.h makes and feed every frame that
 *                                        has an event through common/platform/input.c
 *
 * Whatever the bytes, the parser must return true or false without reading out of bounds, leaking
 * or overflowing; a script it accepts is sorted by frame, within its limits, and has a mark before
 * any check.
 */
#include "input.h"
#include "input_script.h"

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size);
    if (!text)
        return 0;
    input_script s;
    if (input_script_parse(text, "fuzz.script", &s)) {
        if (s.count < 0 || s.count > SCRIPT_EVENTS_MAX || (s.count > 0) != (s.events != NULL))
            abort();
        bool marked = false;
        for (int i = 0; i < s.count; i++) {
            const script_event *e = &s.events[i];
            if (e->frame < 0 || (i > 0 && e->frame < s.events[i - 1].frame))
                abort(); /* sorted by frame */
            if (e->kind < SCRIPT_KEY || e->kind > SCRIPT_QUIT || (e->kind == SCRIPT_SCREENSHOT) != (e->path != NULL) ||
                (e->path && strlen(e->path) == 0))
                abort();
            marked |= e->kind == SCRIPT_OBJECTS_MARK;
            if (e->kind == SCRIPT_OBJECTS_CHECK && !marked)
                abort();
        }
        /* Each frame with events once, as the runner would reach it; the range must cover them.
         * The first 1000 such frames only: a range of a million frames would make every input of
         * that shape a timeout of the harness, not of the parser. */
        input_reset();
        for (int i = 0, frames = 0; i < s.count && frames < 1000; frames++) {
            int first, count;
            input_script_range(&s, s.events[i].frame, &first, &count);
            if (first != i || count < 1)
                abort();
            input_script_feed(&s, s.events[i].frame);
            while (input_take_key() != 0) {
            }
            input_take_mouse();
            i += count;
        }
        if (input_script_last_frame(&s) != (s.count ? s.events[s.count - 1].frame : -1))
            abort();
        input_script_destroy(&s);
    }
    free(text);
    return 0;
}
