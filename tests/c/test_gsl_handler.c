/* GSL's process-wide error handler and the library (elastica.h's header comment):
 * a program that left GSL's default (abort) gets it switched off at the library's
 * first GSL call; a program that installed its own handler before keeps it. */
#include "testutil.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_log.h>
#include <sys/wait.h>
#include <unistd.h>

static int handler_calls;
static void count_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason; (void)file; (void)line; (void)gsl_errno;
    handler_calls++;
}

/* any entry point that uses GSL (it calls el__gsl_quiet first) */
static void first_library_call(void)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 2.0), EL_OK);
}

START_TEST(default_handler_is_switched_off)
{
    const pid_t pid = fork();
    ck_assert(pid >= 0);
    if (pid == 0) {               /* GSL's default handler: log(-1) would abort */
        first_library_call();
        gsl_sf_result r;
        _exit(gsl_sf_log_e(-1.0, &r) == GSL_EDOM ? 0 : 1);
    }
    int status;
    ck_assert(waitpid(pid, &status, 0) == pid);
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0,
                  "GSL's default handler still on after the library's first call (status %d)", status);
}
END_TEST

START_TEST(callers_own_handler_is_kept)
{
    gsl_set_error_handler(count_handler);
    first_library_call();
    gsl_sf_result r;
    handler_calls = 0;
    ck_assert_int_eq(gsl_sf_log_e(-1.0, &r), GSL_EDOM);
    ck_assert_int_eq(handler_calls, 1);
    ck_assert(gsl_set_error_handler(NULL) == count_handler);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("gsl_handler");
    TCase *t = tcase_create("handler");
    tcase_add_test(t, default_handler_is_switched_off);
    tcase_add_test(t, callers_own_handler_is_kept);
    suite_add_tcase(s, t);
    return test_run_suite(s);
}
