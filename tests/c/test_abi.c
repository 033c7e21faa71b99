/* el_abi_digest: the library states the header it was built from, the CRC-32 of
 * include/elastica.h's declarations (the file without its C++ guard and preprocessor
 * lines: what the Python binding's cffi reads), the number elastica_abi.h gives C
 * programs. Computed here from the header itself, not from the build's tool. */
#include "testutil.h"
#include "elastica_abi.h"
#include <stdio.h>
#include <string.h>

/* zlib's CRC-32 (reflected, polynomial 0xEDB88320), bit by bit */
static unsigned long crc32_of(const char *s, size_t n)
{
    unsigned long c = 0xffffffffUL;
    for (size_t i = 0; i < n; i++) {
        c ^= (unsigned char)s[i];
        for (int b = 0; b < 8; b++) c = (c >> 1) ^ (0xedb88320UL & (0UL - (c & 1UL)));
    }
    return c ^ 0xffffffffUL;
}

/* The header's declarations: each "#ifdef __cplusplus" .. "#endif" span cut out, then
 * the lines whose first non-blank character is '#' dropped, the rest joined by '\n'. */
static char *declarations(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    fseek(f, 0, SEEK_END);
    const long size = ftell(f);
    rewind(f);
    char *text = calloc((size_t)size + 1, 1), *out = calloc((size_t)size + 1, 1);
    ck_assert(text && out && fread(text, 1, (size_t)size, f) == (size_t)size);
    fclose(f);
    for (char *g; (g = strstr(text, "#ifdef __cplusplus")) != NULL;) {
        char *e = strstr(g, "#endif");
        ck_assert(e != NULL);
        memmove(g, e + 6, strlen(e + 6) + 1);
    }
    size_t m = 0;
    int first = 1;
    for (char *line = text; *line;) {
        char *end = strchr(line, '\n');
        const size_t len = end ? (size_t)(end - line) : strlen(line);
        const char *c = line;
        while (c < line + len && (*c == ' ' || *c == '\t')) c++;
        if (!(c < line + len && *c == '#')) {
            if (!first) out[m++] = '\n';
            memcpy(out + m, line, len);
            m += len;
            first = 0;
        }
        line += len + (end != NULL);
    }
    free(text);
    *n = m;
    return out;
}

START_TEST(digest_is_the_headers)
{
    size_t n;
    char *decl = declarations("../../include/elastica.h", &n);
    ck_assert_msg(n > 10000 && strstr(decl, "el_abi_digest(void);") && !strstr(decl, "#define"),
                  "declarations of %zu characters", n);
    const unsigned long crc = crc32_of(decl, n);
    free(decl);
    ck_assert_msg(el_abi_digest() == crc, "el_abi_digest %#lx, the header's declarations %#lx",
                  el_abi_digest(), crc);
    ck_assert_msg(EL_ABI_DIGEST == crc, "EL_ABI_DIGEST %#lx, the header's declarations %#lx",
                  (unsigned long)EL_ABI_DIGEST, crc);
}
END_TEST

/* The version macros agree with each other and with the library's el_version() (a
 * library built from this header); the Makefile reads its VERSION from EL_VERSION_STRING
 * (check-install compares pkg-config's with it). */
START_TEST(version_macros_are_the_librarys)
{
    char v[64];
    snprintf(v, sizeof v, "%d.%d.%d", EL_VERSION_MAJOR, EL_VERSION_MINOR, EL_VERSION_PATCH);
    ck_assert_str_eq(v, EL_VERSION_STRING);
    ck_assert_str_eq(el_version(), EL_VERSION_STRING);
}
END_TEST

START_TEST(crc32_is_zlibs)
{
    /* zlib.crc32(b"123456789") == 0xcbf43926, the CRC-32 check value */
    ck_assert_uint_eq(crc32_of("123456789", 9), 0xcbf43926UL);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("abi");
    TCase *t = tcase_create("digest");
    tcase_add_test(t, crc32_is_zlibs);
    tcase_add_test(t, digest_is_the_headers);
    tcase_add_test(t, version_macros_are_the_librarys);
    suite_add_tcase(s, t);
    return test_run_suite(s);
}
