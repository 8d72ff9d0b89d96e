/* Private helpers shared by the deck module's sources (model.c, deck.c, check.c). */
#pragma once
#include <thermoslide/model.h>

/* printf prefix and arguments for "file:line: " of a TslLoc, for SETERRQ messages. */
#define TSL_LOC_FMT        "%s:%" PetscInt_FMT ": "
#define TSL_LOC_ARGS(m, l) TslDeckFileName((m), (l).file), (l).line

/* Path of file index f, or "<unknown>" when there is none. */
const char *TslDeckFileName(const TslModel *model, PetscInt f);

/* Case-insensitive name equality. */
PetscBool TslDeckNameEqual(const char *a, const char *b);

/* Grows *ptr (elements of size sz) so that it can hold n+1 elements when it currently holds n. Arrays grown
 * this way have capacity max(8, next power of two >= n), so no capacity needs storing. New memory is zeroed. */
PetscErrorCode TslDeckGrow(void *ptr, size_t sz, PetscInt n);
