/* The arithmetic of *PARAMETER's data lines (Abaqus: "name = expression", in Python's syntax): numbers, the
 * names of parameters defined before, + - * / ** and parentheses, with Python's precedence: ** binds tighter
 * than a sign on its left and groups to the right (-2**2 = -4, 2**3**2 = 512), / is real division. A plain
 * recursive descent on the text, one function per precedence level; no PETSc objects, so that the reader
 * words the error with the deck's file and line. */
#include "deck_impl.h"
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
  const char   *p; /* next character */
  TslDeckLookup lookup;
  void         *ctx;
  TslExprStatus status;             /* the first failure */
  char          name[TSL_NAME_LEN]; /* the undefined name, for the message */
} Expr;

static void Fail(Expr *e, TslExprStatus status)
{
  if (e->status == TSL_EXPR_OK) e->status = status;
}

static void Blank(Expr *e)
{
  while (isspace((unsigned char)*e->p)) e->p++;
}

PetscBool TslDeckIsIdentifierStart(char c)
{
  return (PetscBool)(isalpha((unsigned char)c) || c == '_');
}

PetscBool TslDeckIsIdentifierChar(char c)
{
  return (PetscBool)(isalnum((unsigned char)c) || c == '_');
}

static PetscReal Sum(Expr *e);
static PetscReal Signed(Expr *e);

/* digits with an optional point and exponent (also Fortran's D, as the deck's numbers take it) */
static PetscReal Number(Expr *e)
{
  char        buf[64];
  size_t      n      = 0;
  const char *q      = e->p;
  PetscBool   digits = PETSC_FALSE;

  while (isdigit((unsigned char)*q)) q++, digits = PETSC_TRUE;
  if (*q == '.') q++;
  while (isdigit((unsigned char)*q)) q++, digits = PETSC_TRUE;
  if (digits && strchr("eEdD", *q) && *q) {
    const char *x = q + 1;
    if (*x == '+' || *x == '-') x++;
    if (isdigit((unsigned char)*x)) {
      while (isdigit((unsigned char)*x)) x++;
      q = x;
    }
  }
  if (!digits || (size_t)(q - e->p) >= sizeof(buf)) {
    Fail(e, TSL_EXPR_MALFORMED);
    return 0;
  }
  for (const char *c = e->p; c < q; c++) buf[n++] = (*c == 'd' || *c == 'D') ? 'e' : *c;
  buf[n] = 0;
  e->p   = q;
  return (PetscReal)strtod(buf, NULL);
}

static PetscReal Name(Expr *e)
{
  size_t    n = 0;
  PetscReal v = 0;

  while (TslDeckIsIdentifierChar(*e->p)) {
    if (n < sizeof(e->name) - 1) e->name[n++] = *e->p;
    e->p++;
  }
  e->name[n] = 0;
  if (!e->lookup(e->ctx, e->name, &v)) Fail(e, TSL_EXPR_UNDEFINED);
  return v;
}

/* a number, a name or a parenthesised expression */
static PetscReal Primary(Expr *e)
{
  Blank(e);
  if (*e->p == '(') {
    PetscReal x;
    e->p++;
    x = Sum(e);
    Blank(e);
    if (*e->p == ')')
      e->p++;
    else
      Fail(e, TSL_EXPR_MALFORMED);
    return x;
  }
  if (isdigit((unsigned char)*e->p) || *e->p == '.') return Number(e);
  if (TslDeckIsIdentifierStart(*e->p)) return Name(e);
  Fail(e, TSL_EXPR_MALFORMED);
  return 0;
}

/* primary [** signed]: the exponent may carry a sign (2**-1) and groups to the right */
static PetscReal Power(Expr *e)
{
  PetscReal x = Primary(e);

  Blank(e);
  if (e->p[0] == '*' && e->p[1] == '*') {
    e->p += 2;
    x = PetscPowReal(x, Signed(e));
  }
  return x;
}

static PetscReal Signed(Expr *e)
{
  Blank(e);
  if (*e->p == '-') return e->p++, -Signed(e);
  if (*e->p == '+') return e->p++, Signed(e);
  return Power(e);
}

static PetscReal Product(Expr *e)
{
  PetscReal x = Signed(e);

  for (;;) {
    Blank(e);
    if (e->p[0] == '*' && e->p[1] != '*') {
      e->p++;
      x *= Signed(e);
    } else if (e->p[0] == '/') {
      PetscReal y;
      e->p++;
      y = Signed(e);
      if (y == 0)
        Fail(e, TSL_EXPR_DIVISION_BY_ZERO);
      else
        x /= y;
    } else
      return x;
  }
}

static PetscReal Sum(Expr *e)
{
  PetscReal x = Product(e);

  for (;;) {
    Blank(e);
    if (*e->p == '+')
      e->p++, x += Product(e);
    else if (*e->p == '-')
      e->p++, x -= Product(e);
    else
      return x;
  }
}

TslExprStatus TslDeckEvaluate(const char *text, TslDeckLookup lookup, void *ctx, PetscReal *value, char name[TSL_NAME_LEN])
{
  Expr e = {text, lookup, ctx, TSL_EXPR_OK, ""};

  *value = Sum(&e);
  Blank(&e);
  if (*e.p) Fail(&e, TSL_EXPR_MALFORMED); /* text left over: "2 3", "a)" */
  if (e.status == TSL_EXPR_OK && !isfinite(*value)) Fail(&e, TSL_EXPR_NOT_FINITE);
  memcpy(name, e.name, TSL_NAME_LEN);
  return e.status;
}

const char *TslDeckExprMessage(TslExprStatus status)
{
  static const char *const msg[] = {
      [TSL_EXPR_OK]               = "",
      [TSL_EXPR_MALFORMED]        = "malformed expression (numbers, names of parameters defined before, + - * / ** and parentheses)",
      [TSL_EXPR_UNDEFINED]        = "undefined parameter",
      [TSL_EXPR_DIVISION_BY_ZERO] = "division by zero",
      [TSL_EXPR_NOT_FINITE]       = "the value is not a finite number",
  };
  return msg[status];
}
