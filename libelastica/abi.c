/* The ABI digest: which header the library was built from (el_abi_digest). */
#include "elastica.h"
#include "elastica_abi.h" /* EL_ABI_DIGEST, written by the build (python/libelastica/_cdef.py --abi) */

unsigned long el_abi_digest(void) { return EL_ABI_DIGEST; }
