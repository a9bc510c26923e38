/* SPDX-License-Identifier: Apache-2.0 */
/* Runs what the header-compile objects built: proof that both link and work. */
#include <stdio.h>

int enteron_header_check_c99(void);
int enteron_header_check_cxx(void);

int main(void) {
    const int c99 = enteron_header_check_c99();
    const int cxx = enteron_header_check_cxx();
    if (c99 != 0 || cxx != 0) {
        fprintf(stderr, "header check failed: C99 part %d, C++ part %d\n", c99, cxx);
        return 1;
    }
    printf("enteron.h compiles and works as C99 and as C++17\n");
    return 0;
}
