/*
 * The libFuzzer target (clang -fsanitize=fuzzer,address,undefined): the same
 * entries and checks as the driver, coverage-guided. A finding other than a
 * sanitizer report (non-finite output, undocumented status, GSL's handler
 * called, ...) is printed and turned into a crash with abort(), so libFuzzer
 * saves the input (crash-<sha1>); `build/fuzz/driver --trace --replay FILE`
 * then shows its arguments. FUZZ_KNOWN=fuzz/known-findings: those findings
 * (other owners' open issues) are printed once each and do not stop the run;
 * their count is the last line.
 */
#include "fuzz.h"

#include <stdio.h>
#include <stdlib.h>

static int fatal;                  /* findings of this input not in the known list */
static unsigned long long nknown;  /* known findings seen */

static void sink(const fz_entry *e, const char *kind, const char *msg)
{
    if (fz_is_known(e->name, kind)) {
        if (nknown++ < 20) fprintf(stderr, "KNOWN %s %s: %s\n", kind, e->name, msg);
        return;
    }
    fprintf(stderr, "FINDING %s %s: %s\n", kind, e->name, msg);
    fatal = 1;
}

static void summary(void)
{
    fprintf(stderr, "libfuzzer: %llu findings of fuzz/known-findings tolerated\n", nknown);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        const char *known = getenv("FUZZ_KNOWN");
        if (known) fz_read_known(known);
        fz_init();
        atexit(summary);
        ready = 1;
    }
    fatal = 0;
    fz_run(data, size, sink);
    if (fatal) abort();
    return 0;
}
