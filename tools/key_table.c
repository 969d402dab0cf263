/* key_table.c - print the course's window keys as the README's Markdown table (common/platform/keys.c).
 *
 *   key_table        the table, to paste between the README's <!-- keys --> markers; the test
 *                    keys.readme fails when the README's copy differs
 */
#include "keys.h"

#include <stdio.h>

int main(void)
{
    keys_print_markdown(stdout);
    return 0;
}
