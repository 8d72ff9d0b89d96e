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

/* Conventional shells (shell.c). TslDeckShellType: for a shell type name (S8RT, SAX2T, or CalculiX's S8R, SAX2)
 * *shell its name, *type the catalogue type it is expanded into, *nnode its own node count and *what the two
 * elements it becomes (for the log); *shell NULL for
 * any other name. TslDeckExpandShells: each shell element read (fewer nodes than its type) expanded into two
 * elements through its thickness, with its faces, sets and node conditions (before TslModelCheck). */
PetscErrorCode TslDeckShellType(const char *name, const char **shell, PetscInt *type, PetscInt *nnode, const char **what);
PetscErrorCode TslDeckExpandShells(TslModel *model);

/* *PARAMETER's expressions (expr.c): numbers, names of parameters, + - * / ** and parentheses, in Python's
 * precedence. lookup gives the value of the parameter called name, or PETSC_FALSE when there is none.
 * TslDeckEvaluate returns the first failure (name: the undefined name), TslDeckExprMessage its words. */
typedef enum { TSL_EXPR_OK, TSL_EXPR_MALFORMED, TSL_EXPR_UNDEFINED, TSL_EXPR_DIVISION_BY_ZERO, TSL_EXPR_NOT_FINITE } TslExprStatus;
typedef PetscBool (*TslDeckLookup)(void *ctx, const char *name, PetscReal *value);
TslExprStatus TslDeckEvaluate(const char *text, TslDeckLookup lookup, void *ctx, PetscReal *value, char name[TSL_NAME_LEN]);
const char   *TslDeckExprMessage(TslExprStatus status);
/* A parameter name: a letter or _, then letters, digits and _. */
PetscBool TslDeckIsIdentifierStart(char c);
PetscBool TslDeckIsIdentifierChar(char c);
