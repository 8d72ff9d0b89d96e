/* The keyword-deck reader (Abaqus/CalculiX dialect), rank 0 only.
 *
 * Layers, bottom up:
 *  - raw lines: RawNext() walks the files (a stack for *INCLUDE, handled here so that an include may
 *    sit anywhere, even between the data lines of a keyword), skips comments and blank lines, and can
 *    push one line back. File texts live until the end of the read so line pointers stay valid.
 *  - logical lines: a keyword line (continued while it ends with a comma) parsed into the keyword
 *    and its parameters (kept in kwbuf for the whole keyword), and data lines split into fields (buf).
 *  - keywords: one table row per keyword with where it may appear, the parameters it knows (others
 *    are warned about) and its handler, which reads its own data lines.
 * Every error is PETSC_ERR_USER_INPUT with "file:line: " first. The reader keeps all its temporary
 * memory in the Deck so that an error path frees everything (tests run with -malloc_dump).
 */
#include "deck_impl.h"
#include <thermoslide/element.h>
#include <ctype.h>
#include <dirent.h>
#include <unistd.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <stddef.h>
#include <string.h>
#include <sys/stat.h>

#define DECK_MAX_DEPTH 16
#define DECK_MAX_PARAM 32

typedef struct {
  char    *text;
  size_t   pos, len;
  PetscInt file, line;
} DeckFrame;

typedef struct {
  TslModel *m;
  DeckFrame frame[DECK_MAX_DEPTH];
  PetscInt  depth;
  char    **texts; /* every file's text, freed at the end */
  PetscInt  ntext;

  /* the deck as read (TslDeckReadFlat): every line RawNext takes from a file but *INCLUDE lines; flat_kw where the last
   * keyword line starts in it */
  PetscBool record;
  char     *flat;
  size_t    flatlen, flatcap, flat_kw;
  /* *RESTART, READ: the old job's deck copy is read as an include at frame depth restart_depth - 1, up to the end of
   * its step restart_stop (1-based; 0: none pending) */
  PetscInt restart_stop, restart_depth;
  /* *POST OUTPUT: the POST OUTPUT deck's frame depth (0: none); post_own: the old job's deck copy is read and the
   * keywords are the POST OUTPUT deck's own again (its output requests, KwOutputRequest) */
  PetscInt  post_depth;
  PetscBool post_own;

  /* raw line pushback */
  PetscBool back;
  char     *raw;
  TslLoc    rawloc;
  PetscBool raw_verbatim; /* raw was read verbatim (no <name> substitution) */

  /* *PARAMETER: the parameters defined so far; every later line has its <name> references replaced by their
   * values (Substitute) into subst, except *HEADING's free text (verbatim) */
  struct DeckParameter *parameters;
  PetscInt              nparameter;
  char                 *subst;
  size_t                substcap;
  PetscBool             verbatim;

  /* current data line */
  char    *buf;
  size_t   bufcap;
  char   **field;
  PetscInt nfield;
  TslLoc   loc;

  /* current keyword line */
  char    *kwbuf;
  size_t   kwcap;
  char    *kw;
  PetscInt nparam;
  char    *pkey[DECK_MAX_PARAM], *pval[DECK_MAX_PARAM];
  TslLoc   kwloc;

  /* state */
  PetscInt  step;                /* index of the open step or -1 */
  PetscInt  material;            /* material the property keywords apply to, or -1 */
  PetscInt  interaction;         /* surface interaction the interface-law keywords apply to, or -1 */
  PetscInt  out_frequency;       /* *OUTPUT, FREQUENCY= in the open step */
  PetscInt  out_frequency_model; /* *OUTPUT, FREQUENCY= in the model data: each step's default */
  PetscInt  restart_frequency, restart_interval; /* *RESTART, WRITE in force (model data or an earlier step): the next step's */
  PetscBool restart_overlay;
  TslLoc    restart_loc;
  PetscInt  out_number_model;    /* *OUTPUT, NUMBER INTERVAL= in the model data: each step's default (0: none) */
  PetscReal out_time_model;      /* *OUTPUT, TIME INTERVAL= in the model data: each step's default (0: none) */
  PetscInt *node_line;           /* [2*nnode] (file, line) of each node, for duplicate messages */
  PetscInt  nkeyword;            /* keyword lines read */

  /* *BOUNDARY in the model data: applies from the first step on (TslDeckRead hands it to that step) */
  PetscInt nmload;
  TslLoad *mload;

  /* parts and instances (see "Parts and instances" below) */
  struct DeckPart     *parts;
  PetscInt             npart;
  struct DeckInstance *inst;
  PetscInt             ninst;
  PetscInt             part;     /* the open *PART, or -1 */
  PetscInt             instance; /* the open *INSTANCE, or -1 */
  PetscBool            assembly; /* inside *ASSEMBLY ... *END ASSEMBLY */
  TslLoc               assembly_loc;

  PetscBool pore;      /* a pore pressure element type was read (its dof 8 is accepted, and not active) */
  PetscBool skip_line; /* set by a load's line function: the line is read and left out (a *BOUNDARY on dof 8) */
  PetscBool          node_normal_warned; /* the warning that *NODE normal directions are ignored was given */
  TslLoc            *type_note;          /* per catalogue row: the first *ELEMENT that reached it by CalculiX's mechanical name
                                            (C3D8 for C3D8T; line 0: none), noted once the procedures are known (DeckTypeNotes) */
  PetscBool         *type_mech;          /* per catalogue row: type_note is an *ELEMENT by the mechanical name */
  PetscBool          shell_noted;        /* the note that conventional shells are expanded was given */
  PetscBool          dof0_noted;         /* the note that dof 0 is read as 11 in heat transfer was given (HeatDofZero) */
} Deck;

/* A part (*PART ... *END PART), read straight into the model with its ids shifted past those defined before
 * it and its set, surface and section names qualified by the part's name until its first instance renames
 * them; a further instance copies what the first one holds. */
typedef struct DeckPart {
  char       name[TSL_NAME_LEN];
  PetscInt   node_off, elem_off; /* added to the part's own ids */
  PetscInt   node_first, node_n; /* its nodes in the model's arrays */
  PetscInt   elem_first, elem_n; /* its elements */
  PetscInt   nsets[3];           /* node sets, element sets and surfaces in the model before the part */
  PetscInt   nsection;           /* sections in the model before the part */
  PetscInt   nt[2];              /* its *NODAL THICKNESS lines in the model's list: [nt[0], nt[1]) */
  PetscReal *xyz;                /* its nodes' coordinates as the part gives them (3 per node) */
  PetscInt   first;              /* its first instance, or -1 */
  TslLoc     loc;
} DeckPart;

/* A *PARAMETER: its name (case-insensitive, as the deck's other names) and value. */
typedef struct DeckParameter {
  char      name[TSL_NAME_LEN];
  PetscReal value;
} DeckParameter;

/* An instance: the part placed, its ids (offsets) and names ("name.x"). */
typedef struct DeckInstance {
  char     name[TSL_NAME_LEN];
  PetscInt part, node_off, elem_off;
} DeckInstance;

#define LOC_FMT            TSL_LOC_FMT
#define DLOC(d)            TSL_LOC_ARGS((d)->m, (d)->loc)
#define KLOC(d)            TSL_LOC_ARGS((d)->m, (d)->kwloc)
#define USER_ERR(...)      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, __VA_ARGS__)
#define USER_CHECK(c, ...) PetscCheck(c, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, __VA_ARGS__)
/* Why a *CONTROLS other than TIME INCREMENTATION, FIELD or RESET is read past (docs/keywords.md, *CONTROLS). */
#define CONTROLS_NOTE                                                                                                                                \
  "only PARAMETERS=TIME INCREMENTATION, FIELD and RESET are read; the solver's own line search applies (docs/running.md)"
/* Why the pore fluid's data is read past (docs/elements.md, "Pore pressure types"). */
#define PORE_FLUID_NOTE "pore fluid flow is not modelled (the pore pressure of CPE4PT, ... is not active in coupled temperature-displacement steps)"

/* ---- small string helpers -------------------------------------------------------------------- */

static char *Trim(char *s)
{
  char *e;
  while (*s && isspace((unsigned char)*s)) s++;
  e = s + strlen(s);
  while (e > s && isspace((unsigned char)e[-1])) *--e = 0;
  return s;
}

/* Upper case, runs of blanks collapsed to one space, trimmed; in place. */
static char *Normalize(char *s)
{
  char *r = Trim(s), *w = r;
  for (char *p = r; *p; p++) {
    if (isspace((unsigned char)*p)) {
      if (w > r && w[-1] != ' ') *w++ = ' ';
    } else
      *w++ = (char)toupper((unsigned char)*p);
  }
  *w = 0;
  return r;
}

static PetscBool IsInteger(const char *s)
{
  if (*s == '+' || *s == '-') s++;
  if (!*s) return PETSC_FALSE;
  for (; *s; s++)
    if (!isdigit((unsigned char)*s)) return PETSC_FALSE;
  return PETSC_TRUE;
}

static PetscErrorCode BufReserve(char **buf, size_t *cap, size_t need)
{
  PetscFunctionBeginUser;
  if (need <= *cap) PetscFunctionReturn(PETSC_SUCCESS);
  *cap = need < 256 ? 256 : 2 * need;
  PetscCall(PetscRealloc(*cap, buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- numbers --------------------------------------------------------------------------------- */

/* A real in C or Fortran form (1.e6, 1.0D3, 30.0E+06). */
static PetscErrorCode DeckReal(Deck *d, const char *s, const char *what, PetscReal *x)
{
  char   tmp[64], *end;
  size_t n = strlen(s);

  PetscFunctionBeginUser;
  USER_CHECK(n > 0, LOC_FMT "missing value for %s", DLOC(d), what);
  USER_CHECK(n < sizeof(tmp), LOC_FMT "expected a number for %s, got '%s'", DLOC(d), what, s);
  for (size_t i = 0; i <= n; i++) tmp[i] = (s[i] == 'd' || s[i] == 'D') ? 'e' : s[i];
  errno = 0;
  *x    = (PetscReal)strtod(tmp, &end);
  /* ERANGE on underflow (1e-400) gives a correctly rounded tiny number: only overflow is an error */
  USER_CHECK(end != tmp && *end == 0 && !(errno == ERANGE && PetscAbsReal(*x) > 1) && !PetscIsInfOrNanReal(*x),
             LOC_FMT "expected a number for %s, got '%s'", DLOC(d), what, s);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DeckInt(Deck *d, const char *s, const char *what, PetscInt *x)
{
  long  v;
  char *end;

  PetscFunctionBeginUser;
  USER_CHECK(*s, LOC_FMT "missing value for %s", DLOC(d), what);
  errno = 0;
  v     = strtol(s, &end, 10);
  USER_CHECK(end != s && *end == 0 && errno != ERANGE && v == (PetscInt)v, LOC_FMT "expected an integer for %s, got '%s'", DLOC(d), what, s);
  *x = (PetscInt)v;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Field i as a real, or def when absent or blank. */
static PetscErrorCode FieldRealDefault(Deck *d, PetscInt i, const char *what, PetscReal def, PetscReal *x)
{
  PetscFunctionBeginUser;
  if (i >= d->nfield || !d->field[i][0])
    *x = def;
  else
    PetscCall(DeckReal(d, d->field[i], what, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* As FieldRealDefault, and a zero also takes the default: the dialect's increment limits, where CalculiX's own
 * decks write 0 for "not given" (its test deck contact9.inp: ".000001,.0024,0.,0.00005"). */
static PetscErrorCode FieldRealDefaultZero(Deck *d, PetscInt i, const char *what, PetscReal def, PetscReal *x)
{
  PetscFunctionBeginUser;
  PetscCall(FieldRealDefault(d, i, what, def, x));
  if (*x == 0) *x = def;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FieldReal(Deck *d, PetscInt i, const char *what, PetscReal *x)
{
  PetscFunctionBeginUser;
  USER_CHECK(i < d->nfield, LOC_FMT "missing value for %s", DLOC(d), what);
  PetscCall(DeckReal(d, d->field[i], what, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FieldInt(Deck *d, PetscInt i, const char *what, PetscInt *x)
{
  PetscFunctionBeginUser;
  USER_CHECK(i < d->nfield, LOC_FMT "missing value for %s", DLOC(d), what);
  PetscCall(DeckInt(d, d->field[i], what, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A node or element id: a positive integer in the dialect. Elsewhere a negative id means "no target"
 * (TslTarget), so a node -1 would silently be no node at all. */
static PetscErrorCode DeckId(Deck *d, const char *s, const char *what, PetscInt *x)
{
  PetscFunctionBeginUser;
  PetscCall(DeckInt(d, s, what, x));
  USER_CHECK(*x >= 1, LOC_FMT "%s must be a positive integer, got '%s'", DLOC(d), what, s);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FieldId(Deck *d, PetscInt i, const char *what, PetscInt *x)
{
  PetscFunctionBeginUser;
  USER_CHECK(i < d->nfield, LOC_FMT "missing value for %s", DLOC(d), what);
  PetscCall(DeckId(d, d->field[i], what, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CopyName(Deck *d, TslLoc loc, char dst[TSL_NAME_LEN], const char *src)
{
  PetscFunctionBeginUser;
  USER_CHECK(strlen(src) < TSL_NAME_LEN, LOC_FMT "name '%s' is longer than %d characters", TSL_LOC_ARGS(d->m, loc), src, TSL_NAME_LEN - 1);
  PetscCall(PetscStrncpy(dst, src, TSL_NAME_LEN));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- parts and instances ----------------------------------------------------------------------
 * Abaqus/CAE writes a model as parts (*PART: nodes, elements, sets, surfaces and sections, each part numbered
 * from 1) placed by instances in an assembly (*INSTANCE, NAME=i, PART=p with an optional translation and
 * rotation), and refers to a part's sets as "i.name" from the assembly and the steps. Read flat here: a part's
 * ids are shifted past every id defined before it (the first part keeps its own), its names are qualified
 * ("p.name" while the part is read, renamed "i.name" by its first instance) and its instance moves its
 * nodes; a further instance of the part copies its nodes, elements, sets, surfaces and sections with ids
 * shifted past every id defined before it and names qualified by that instance. */

/* name as the deck means it here: qualified by the open part, if any */
static PetscErrorCode Scoped(Deck *d, TslLoc loc, const char *name, char out[TSL_NAME_LEN])
{
  PetscFunctionBeginUser;
  if (d->part < 0)
    PetscCall(CopyName(d, loc, out, name));
  else {
    char buf[2 * TSL_NAME_LEN + 2];
    PetscCall(PetscSNPrintf(buf, sizeof(buf), "%s.%s", d->parts[d->part].name, name));
    PetscCall(CopyName(d, loc, out, buf));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the shift of node (element) ids read here: instance inst's (an assembly set's INSTANCE=, a label "i.n"),
 * else the open part's */
static PetscInt IdShift(const Deck *d, PetscInt inst, PetscBool node)
{
  if (inst >= 0) return node ? d->inst[inst].node_off : d->inst[inst].elem_off;
  if (d->part < 0) return 0;
  return node ? d->parts[d->part].node_off : d->parts[d->part].elem_off;
}

/* the largest (smallest) of n ids; 0 for none */
static PetscInt IdMax(const PetscInt *ids, PetscInt n)
{
  PetscInt x = 0;
  for (PetscInt i = 0; i < n; i++) x = PetscMax(x, ids[i]);
  return x;
}

static PetscInt IdMin(const PetscInt *ids, PetscInt n)
{
  PetscInt x = n ? ids[0] : 0;
  for (PetscInt i = 1; i < n; i++) x = PetscMin(x, ids[i]);
  return x;
}

/* the instance called name, or -1 */
static PetscInt InstanceFind(const Deck *d, const char *name)
{
  for (PetscInt i = 0; i < d->ninst; i++)
    if (TslDeckNameEqual(d->inst[i].name, name)) return i;
  return -1;
}

/* ---- files and raw lines --------------------------------------------------------------------- */

/* Why path cannot be read as a deck, or NULL: fopen() opens a directory on Linux and ftell() then
 * gives a nonsense length, so the file's type is looked at first. */
static const char *DeckFileProblem(const char *path)
{
  struct stat st;

  if (stat(path, &st)) return strerror(errno);
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return "is not a regular file";
  return NULL;
}

/* A keyword line read ahead and given back (RawUnget) when a file is opened in the keyword's place (DeckOpen: *POST
 * OUTPUT's data lines are followed by the old deck copy) goes back into its file, so that it is read after the opened
 * file, not before it. It came from the top frame (a data line loop reads ahead in the frame it reads): its end, turned
 * into a NUL when it was read, is a newline again and the frame's position its start. */
static void RawRewind(Deck *d)
{
  DeckFrame *f;
  size_t     start;

  if (!d->back || d->depth < 1) return;
  f = &d->frame[d->depth - 1];
  if (f->pos == 0 || d->rawloc.file != f->file) return;
  if (f->text[f->pos - 1] == 0) f->text[f->pos - 1] = '\n';
  start = f->pos - 1;
  while (start > 0 && f->text[start - 1] != 0 && f->text[start - 1] != '\n') start--;
  f->pos  = start;
  f->line = d->rawloc.line - 1;
  d->back = PETSC_FALSE;
  if (d->record) d->flatlen = d->flat_kw, d->flat[d->flatlen] = 0; /* recorded again when it is read again */
}

static PetscErrorCode DeckOpen(Deck *d, const char *path, PetscBool include)
{
  FILE       *fp;
  long        len;
  char       *text, *nul;
  const char *problem = DeckFileProblem(path);
  DeckFrame  *f;

  PetscFunctionBeginUser;
  RawRewind(d); /* a keyword line read ahead belongs after the file opened here */
  fp = problem ? NULL : fopen(path, "rb");
  if (!fp) {
    if (!problem) problem = strerror(errno); /* unreadable */
    if (include) USER_ERR(LOC_FMT "cannot open include file %s: %s", KLOC(d), path, problem);
    USER_ERR("%s:0: cannot open input deck: %s", path, problem);
  }
  USER_CHECK(d->depth < DECK_MAX_DEPTH, LOC_FMT "*INCLUDE nested deeper than %d levels", KLOC(d), DECK_MAX_DEPTH);
  if (fseek(fp, 0, SEEK_END) || (len = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET)) {
    fclose(fp);
    USER_ERR("%s:0: cannot read file", path);
  }
  PetscCall(TslDeckGrow(&d->texts, sizeof(char *), d->ntext));
  PetscCall(PetscMalloc1((size_t)len + 1, &text));
  d->texts[d->ntext++] = text;
  if (len && fread(text, 1, (size_t)len, fp) != (size_t)len) {
    fclose(fp);
    USER_ERR("%s:0: cannot read file", path);
  }
  fclose(fp);
  text[len] = 0;
  /* the reader works on C strings: a NUL byte would silently end its line (and hide the rest of it) */
  nul = memchr(text, 0, (size_t)len);
  if (nul) {
    PetscInt line = 1;
    for (const char *c = text; c < nul; c++) line += *c == '\n';
    USER_ERR("%s:%" PetscInt_FMT ": a NUL byte: this is not a text file", path, line);
  }

  PetscCall(TslDeckGrow(&d->m->files, sizeof(char *), d->m->nfile));
  PetscCall(PetscStrallocpy(path, &d->m->files[d->m->nfile]));
  f       = &d->frame[d->depth++];
  f->text = text;
  /* a UTF-8 byte-order mark (editors on Windows write one) is no part of the first line */
  f->pos  = (len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3)) ? 3 : 0;
  f->len  = (size_t)len;
  f->file = d->m->nfile++;
  f->line = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParseKeyword(Deck *d, char *line);

/* *INCLUDE, INPUT=path: the path is relative to the including file's directory. */
static PetscErrorCode DeckInclude(Deck *d)
{
  const char *input = NULL, *from = d->m->files[d->kwloc.file], *slash;
  char       *path;
  size_t      dirlen, n;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < d->nparam; i++)
    if (!strcmp(d->pkey[i], "INPUT")) input = d->pval[i];
  USER_CHECK(input && input[0], LOC_FMT "*INCLUDE needs INPUT=file", KLOC(d));
  slash  = strrchr(from, '/');
  dirlen = (input[0] == '/' || !slash) ? 0 : (size_t)(slash - from) + 1;
  n      = dirlen + strlen(input) + 1;
  PetscCall(PetscMalloc1(n, &path));
  memcpy(path, from, dirlen);
  memcpy(path + dirlen, input, strlen(input) + 1);
  PetscErrorCode ierr = DeckOpen(d, path, PETSC_TRUE);
  PetscCall(PetscFree(path));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- parameters (*PARAMETER) and their substitution ------------------------------------------ */

static PetscInt ParameterFind(const Deck *d, const char *name)
{
  for (PetscInt i = 0; i < d->nparameter; i++)
    if (TslDeckNameEqual(d->parameters[i].name, name)) return i;
  return -1;
}

static PetscBool ParameterLookup(void *ctx, const char *name, PetscReal *value)
{
  const Deck *d = (const Deck *)ctx;
  PetscInt    i = ParameterFind(d, name);

  if (i < 0) return PETSC_FALSE;
  *value = d->parameters[i].value;
  return PETSC_TRUE;
}

/* The length of the reference "<name>" at s (0: s is no reference, such as "a < b" or "<1>"). */
static size_t ReferenceLength(const char *s)
{
  size_t n = 1;
  if (s[0] != '<' || !TslDeckIsIdentifierStart(s[1])) return 0;
  while (TslDeckIsIdentifierChar(s[n])) n++;
  return s[n] == '>' ? n + 1 : 0;
}

/* *line with every <name> replaced by the parameter's value, written in the fewest digits that read back
 * as the same number (so 4 stays 4, where an integer is wanted), in d->subst; unchanged when it has none.
 * An undefined name is an error at the line. */
static PetscErrorCode Substitute(Deck *d, char **line)
{
  size_t n = 0;

  PetscFunctionBeginUser;
  if (!strchr(*line, '<')) PetscFunctionReturn(PETSC_SUCCESS);
  for (const char *c = *line; *c;) {
    size_t len = ReferenceLength(c);
    char   num[40];
    if (!len) {
      PetscCall(BufReserve(&d->subst, &d->substcap, n + 2));
      d->subst[n++] = *c++;
      continue;
    }
    {
      char     name[TSL_NAME_LEN];
      PetscInt k;
      USER_CHECK(len - 2 < sizeof(name), LOC_FMT "parameter name %.*s is longer than %d characters", TSL_LOC_ARGS(d->m, d->rawloc), (int)len, c,
                 TSL_NAME_LEN - 1);
      memcpy(name, c + 1, len - 2);
      name[len - 2] = 0;
      k             = ParameterFind(d, name);
      USER_CHECK(k >= 0, LOC_FMT "undefined parameter <%s> (a *PARAMETER line before its use defines it)", TSL_LOC_ARGS(d->m, d->rawloc), name);
      PetscCall(PetscSNPrintf(num, sizeof(num), "%.15g", (double)d->parameters[k].value));
      if (strtod(num, NULL) != d->parameters[k].value) PetscCall(PetscSNPrintf(num, sizeof(num), "%.17g", (double)d->parameters[k].value));
    }
    PetscCall(BufReserve(&d->subst, &d->substcap, n + strlen(num) + 1));
    memcpy(d->subst + n, num, strlen(num));
    n += strlen(num);
    c += len;
  }
  d->subst[n] = 0;
  *line       = d->subst;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool IsKeywordLine(const char *s)
{
  return (s[0] == '*' && s[1] != '*') ? PETSC_TRUE : PETSC_FALSE;
}

/* The next non-blank, non-comment physical line (trimmed), or got = FALSE at the end of the deck.
 * *INCLUDE lines are followed here. */
static PetscErrorCode RawNext(Deck *d, const char **s, PetscBool *got)
{
  PetscFunctionBeginUser;
  if (d->back) {
    d->back = PETSC_FALSE;
    if (d->raw_verbatim && !d->verbatim) { /* the line after a *HEADING's text, read ahead: its references now */
      PetscCall(Substitute(d, &d->raw));
      d->raw_verbatim = PETSC_FALSE;
    }
    *s     = d->raw;
    d->loc = d->rawloc;
    *got   = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  *got = PETSC_FALSE;
  while (d->depth > 0) {
    DeckFrame *f = &d->frame[d->depth - 1];
    char      *line, *nl, *orig;
    if (f->pos >= f->len) {
      d->depth--;
      continue;
    }
    line = f->text + f->pos;
    nl   = strchr(line, '\n');
    if (nl) {
      *nl    = 0;
      f->pos = (size_t)(nl - f->text) + 1;
    } else
      f->pos = f->len;
    f->line++;
    line = Trim(line);
    if (!line[0] || (line[0] == '*' && line[1] == '*')) continue;
    orig            = line;
    d->rawloc.file  = f->file;
    d->rawloc.line  = f->line;
    d->raw_verbatim = d->verbatim;
    if (!d->verbatim) PetscCall(Substitute(d, &line));
    if (line[0] == '*') {
      /* cheap test for *INCLUDE before a full parse */
      char   head[16];
      size_t k = 0;
      for (const char *p = line + 1; *p && *p != ',' && k < sizeof(head) - 1; p++)
        if (!isspace((unsigned char)*p)) head[k++] = (char)toupper((unsigned char)*p);
      head[k] = 0;
      if (!strcmp(head, "INCLUDE")) {
        /* an include may come between the data lines of another keyword: keep that keyword's state */
        char    *kw = d->kw, *pkey[DECK_MAX_PARAM], *pval[DECK_MAX_PARAM];
        PetscInt np = d->nparam;
        TslLoc   kl = d->kwloc;
        memcpy(pkey, d->pkey, sizeof(pkey));
        memcpy(pval, d->pval, sizeof(pval));
        d->kwloc = d->rawloc;
        PetscCall(ParseKeyword(d, line));
        PetscCall(DeckInclude(d));
        d->kw = kw, d->nparam = np, d->kwloc = kl;
        memcpy(d->pkey, pkey, sizeof(pkey));
        memcpy(d->pval, pval, sizeof(pval));
        continue;
      }
    }
    if (d->record) { /* the line as in its file, before any <name> substitution */
      const size_t n = strlen(orig);
      if (orig[0] == '*') d->flat_kw = d->flatlen;
      PetscCall(BufReserve(&d->flat, &d->flatcap, d->flatlen + n + 2));
      memcpy(d->flat + d->flatlen, orig, n);
      d->flatlen += n;
      d->flat[d->flatlen++] = '\n';
      d->flat[d->flatlen]   = 0;
    }
    d->raw = line;
    d->loc = d->rawloc;
    *s     = line;
    *got   = PETSC_TRUE;
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void RawUnget(Deck *d)
{
  d->back = PETSC_TRUE;
}

/* ---- logical lines --------------------------------------------------------------------------- */

static PetscInt CountFields(const char *s)
{
  PetscInt n = 0, nonempty = 0;
  for (const char *p = s;; p++) {
    if (*p == ',' || !*p) {
      if (nonempty) n++;
      nonempty = 0;
      if (!*p) break;
    } else if (!isspace((unsigned char)*p))
      nonempty = 1;
  }
  return n;
}

static PetscBool EndsWithComma(const char *s)
{
  size_t n = strlen(s);
  return (n && s[n - 1] == ',') ? PETSC_TRUE : PETSC_FALSE;
}

/* Splits buf at commas into trimmed fields; trailing empty fields (a trailing comma) are dropped. */
static PetscErrorCode SplitFields(Deck *d, char *s)
{
  PetscFunctionBeginUser;
  d->nfield = 0;
  for (;;) {
    char *c = strchr(s, ',');
    if (c) *c = 0;
    PetscCall(TslDeckGrow(&d->field, sizeof(char *), d->nfield));
    d->field[d->nfield++] = Trim(s);
    if (!c) break;
    s = c + 1;
  }
  while (d->nfield > 0 && !d->field[d->nfield - 1][0]) d->nfield--;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The next data line of the current keyword, split into fields; got = FALSE (and nothing consumed)
 * when the next line is a keyword or the deck ends. With want > 0, a line ending in a comma is joined
 * with the following data lines until it has want fields (long *ELEMENT lines). */
static PetscErrorCode DataLine(Deck *d, PetscInt want, PetscBool *got)
{
  const char *s;
  size_t      n;
  TslLoc      first;

  PetscFunctionBeginUser;
  PetscCall(RawNext(d, &s, got));
  if (!*got) PetscFunctionReturn(PETSC_SUCCESS);
  if (IsKeywordLine(s)) {
    RawUnget(d);
    *got = PETSC_FALSE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  first = d->loc;
  n     = strlen(s);
  PetscCall(BufReserve(&d->buf, &d->bufcap, n + 1));
  memcpy(d->buf, s, n + 1);
  while (want > 0 && EndsWithComma(d->buf) && CountFields(d->buf) < want) {
    PetscBool more;
    PetscCall(RawNext(d, &s, &more));
    if (!more) break;
    if (IsKeywordLine(s)) {
      RawUnget(d);
      break;
    }
    n = strlen(d->buf);
    PetscCall(BufReserve(&d->buf, &d->bufcap, n + strlen(s) + 1));
    memcpy(d->buf + n, s, strlen(s) + 1);
  }
  d->loc = first;
  PetscCall(SplitFields(d, d->buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Parses a keyword line (in place) into kw and parameters. */
static PetscErrorCode ParseKeyword(Deck *d, char *line)
{
  char *p = line + 1, *c;

  PetscFunctionBeginUser;
  d->nparam = 0;
  c         = strchr(p, ',');
  if (c) *c = 0;
  d->kw = Normalize(p);
  while (c) {
    char *item = c + 1, *eq;
    c          = strchr(item, ',');
    if (c) *c = 0;
    item = Trim(item);
    if (!item[0]) continue;
    USER_CHECK(d->nparam < DECK_MAX_PARAM, LOC_FMT "too many parameters on *%s", KLOC(d), d->kw);
    eq = strchr(item, '=');
    if (eq) {
      char *v = Trim(eq + 1);
      *eq     = 0;
      if (v[0] == '"') {
        size_t n = strlen(v);
        v++;
        if (n >= 2 && v[n - 2] == '"') v[n - 2] = 0;
      }
      d->pval[d->nparam] = v;
    } else
      d->pval[d->nparam] = NULL;
    d->pkey[d->nparam++] = Normalize(item);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether key is in list ('|'-separated names). */
static PetscBool ParamKnown(const char *list, const char *key)
{
  size_t n = strlen(key);
  for (const char *p = list; *p;) {
    const char *e = strchr(p, '|');
    size_t      l = e ? (size_t)(e - p) : strlen(p);
    if (l == n && !strncmp(p, key, n)) return PETSC_TRUE;
    if (!e) break;
    p = e + 1;
  }
  return PETSC_FALSE;
}

static const char *KeywordParams(const char *name);

/* Whether line, which follows a keyword line ending in a comma, continues it rather than being the keyword's
 * first data line. The dialect continues a keyword line only onto more parameters, and a trailing comma alone
 * is common before data (CalculiX-Examples' leaf spring: "*node file," then "U"): so a line continues it when
 * it gives a value (NAME=value) or holds nothing but parameter names the keyword knows (params, from the
 * keyword table; NULL for an unknown or ignored keyword). */
static PetscBool ContinuesKeyword(const char *line, const char *params)
{
  PetscBool any = PETSC_FALSE;

  if (strchr(line, '=')) return PETSC_TRUE;
  if (!params) return PETSC_FALSE;
  for (const char *p = line;;) {
    const char *c = strchr(p, ',');
    size_t      n = c ? (size_t)(c - p) : strlen(p);
    char        item[64], *w;
    if (n >= sizeof(item)) return PETSC_FALSE;
    memcpy(item, p, n);
    item[n] = 0;
    w       = Normalize(item);
    if (w[0]) {
      if (!ParamKnown(params, w)) return PETSC_FALSE;
      any = PETSC_TRUE;
    }
    if (!c) break;
    p = c + 1;
  }
  return any;
}

/* Reads the keyword line starting at s into kwbuf, joined with the lines that continue it (ContinuesKeyword)
 * while it ends in a comma. */
static PetscErrorCode KeywordLine(Deck *d, const char *s)
{
  size_t      n = strlen(s);
  char        name[64];
  const char *params;

  PetscFunctionBeginUser;
  d->kwloc = d->loc;
  PetscCall(BufReserve(&d->kwbuf, &d->kwcap, n + 1));
  memcpy(d->kwbuf, s, n + 1);
  n = strcspn(s + 1, ",");
  PetscCall(PetscStrncpy(name, s + 1, PetscMin(n + 1, sizeof(name))));
  params = KeywordParams(Normalize(name));
  while (EndsWithComma(d->kwbuf)) {
    PetscBool more;
    PetscCall(RawNext(d, &s, &more));
    if (!more) break;
    if (IsKeywordLine(s) || !ContinuesKeyword(s, params)) {
      RawUnget(d);
      break;
    }
    n = strlen(d->kwbuf);
    PetscCall(BufReserve(&d->kwbuf, &d->kwcap, n + strlen(s) + 1));
    memcpy(d->kwbuf + n, s, strlen(s) + 1);
  }
  PetscCall(ParseKeyword(d, d->kwbuf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- parameters ------------------------------------------------------------------------------ */

static const char *Param(Deck *d, const char *key)
{
  for (PetscInt i = 0; i < d->nparam; i++)
    if (!strcmp(d->pkey[i], key)) return d->pval[i] ? d->pval[i] : "";
  return NULL;
}

static PetscErrorCode ParamRequired(Deck *d, const char *key, const char **val)
{
  PetscFunctionBeginUser;
  *val = Param(d, key);
  USER_CHECK(*val && (*val)[0], LOC_FMT "*%s needs the parameter %s=", KLOC(d), d->kw, key);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Parameter value upper-cased with blanks normalised into buf (for enumerated values). */
static const char *ParamUpper(Deck *d, const char *key, char *buf, size_t len)
{
  const char *v = Param(d, key);
  if (!v) return NULL;
  (void)PetscStrncpy(buf, v, len);
  return Normalize(buf);
}

static PetscErrorCode ParamReal(Deck *d, const char *key, PetscReal *x, PetscBool *set)
{
  const char *v    = Param(d, key);
  TslLoc      save = d->loc;

  PetscFunctionBeginUser;
  if (set) *set = v ? PETSC_TRUE : PETSC_FALSE;
  if (!v) PetscFunctionReturn(PETSC_SUCCESS);
  d->loc = d->kwloc;
  PetscCall(DeckReal(d, v, key, x));
  d->loc = save;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParamInt(Deck *d, const char *key, PetscInt *x)
{
  const char *v    = Param(d, key);
  TslLoc      save = d->loc;

  PetscFunctionBeginUser;
  if (!v) PetscFunctionReturn(PETSC_SUCCESS);
  d->loc = d->kwloc;
  PetscCall(DeckInt(d, v, key, x));
  d->loc = save;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- keyword table --------------------------------------------------------------------------- */

/* Placement: where in the deck a keyword may appear, as in the dialect (Abaqus "model data" / "history
 * data", CalculiX "model definition" / "step"). Bit flags: the model data is everything before the
 * first *STEP, the history data what lies inside *STEP ... *END STEP; between an *END STEP and the
 * next *STEP only *STEP itself may come (*INCLUDE is followed wherever it is, below the table). */
typedef enum { AT_MODEL = 1, AT_STEP = 2, AT_BETWEEN = 4 } DeckPlacement;
#define AT_BOTH (AT_MODEL | AT_STEP)

/* Block: a sub-option fills the block its opening keyword started (material properties follow *MATERIAL,
 * interface laws follow *SURFACE INTERACTION); any other keyword closes the block. */
typedef enum { IN_NONE, IN_MATERIAL, IN_INTERACTION } DeckBlock;

typedef struct DeckKeyword DeckKeyword;
typedef PetscErrorCode (*DeckLoadLine)(Deck *, TslLoad *);
struct DeckKeyword {
  const char   *name;
  DeckPlacement placement;
  DeckBlock     block;
  const char   *params; /* '|'-separated known parameters; NULL: ignored keyword */
  PetscErrorCode (*handler)(Deck *, const DeckKeyword *);
  PetscInt     kind; /* load kind, or output request flags */
  DeckLoadLine line; /* load data-line parser */
};

/* ---- mesh ------------------------------------------------------------------------------------ */

static PetscErrorCode SetAppend(TslSet *s, PetscInt id)
{
  PetscFunctionBeginUser;
  PetscCall(TslDeckGrow(&s->ids, sizeof(PetscInt), s->n));
  s->ids[s->n++] = id;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetFinish(TslSet *s)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSortRemoveDupsInt(&s->n, s->ids));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The set called name in (*sets, *n), created at loc when new. */
static PetscErrorCode SetGet(Deck *d, TslSet **sets, PetscInt *n, const char *name, PetscInt *index)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < *n; i++)
    if (TslDeckNameEqual((*sets)[i].name, name)) {
      *index = i;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  PetscCall(TslDeckGrow(sets, sizeof(TslSet), *n));
  PetscCall(CopyName(d, d->kwloc, (*sets)[*n].name, name));
  (*sets)[*n].loc = d->kwloc;
  *index          = (*n)++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwHeading(Deck *d, const DeckKeyword *kw)
{
  const char *s;
  PetscBool   got, first = PETSC_TRUE;

  PetscFunctionBeginUser;
  (void)kw;
  d->verbatim = PETSC_TRUE; /* a title may say "<" and ">" */
  for (;;) {                /* the text is free-form: take raw lines, commas included */
    PetscCall(RawNext(d, &s, &got));
    if (!got) break;
    if (IsKeywordLine(s)) {
      RawUnget(d);
      break;
    }
    if (first) PetscCall(PetscStrncpy(d->m->heading, s, sizeof(d->m->heading)));
    first = PETSC_FALSE;
  }
  d->verbatim = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwNode(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m    = d->m;
  const char *nset = Param(d, "NSET");
  PetscInt    iset = -1;
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!d->assembly, LOC_FMT "*NODE in an assembly (reference points) is not supported", KLOC(d));
  if (nset) {
    char name[TSL_NAME_LEN];
    USER_CHECK(nset[0], LOC_FMT "NSET= needs a name", KLOC(d));
    PetscCall(Scoped(d, d->kwloc, nset, name));
    PetscCall(SetGet(d, &m->nsets, &m->nnset, name, &iset));
  }
  for (;;) {
    PetscInt id;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield >= 2 && d->nfield <= 7, LOC_FMT "*NODE data line needs: id, x[, y[, z[, normal's nx, ny, nz]]]", DLOC(d));
    PetscCall(FieldId(d, 0, "the node id", &id));
    id += IdShift(d, -1, PETSC_TRUE);
    PetscCall(TslDeckGrow(&m->node_id, sizeof(PetscInt), m->nnode));
    PetscCall(TslDeckGrow(&m->node_xyz, 3 * sizeof(PetscReal), m->nnode));
    PetscCall(TslDeckGrow(&d->node_line, 2 * sizeof(PetscInt), m->nnode));
    m->node_id[m->nnode] = id;
    for (PetscInt c = 0; c < 3; c++) {
      static const char *what[3] = {"the x coordinate", "the y coordinate", "the z coordinate"};
      PetscCall(FieldRealDefault(d, 1 + c, what[c], 0.0, &m->node_xyz[3 * m->nnode + c]));
    }
    for (PetscInt c = 4; c < d->nfield; c++) { /* the dialect's nodal normal (shells, beams): read, so a typo still tells; not used */
      PetscReal n;
      PetscCall(FieldRealDefault(d, c, "a component of the node's normal", 0.0, &n));
    }
    if (d->nfield > 4 && !d->node_normal_warned) {
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            LOC_FMT "warning: *NODE: the normal directions (fields 5-7) are ignored: no element type here uses nodal normals\n",
                            DLOC(d)));
      d->node_normal_warned = PETSC_TRUE;
    }
    d->node_line[2 * m->nnode]     = d->loc.file;
    d->node_line[2 * m->nnode + 1] = d->loc.line;
    m->nnode++;
    if (iset >= 0) PetscCall(SetAppend(&m->nsets[iset], id));
  }
  if (iset >= 0) PetscCall(SetFinish(&m->nsets[iset]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwElement(Deck *d, const DeckKeyword *kw)
{
  TslModel             *m = d->m;
  const char           *tname, *elset = Param(d, "ELSET");
  PetscInt              type, nn, iset = -1;
  const TslElementType *et;
  PetscBool             got;
  const char           *shell = NULL, *what = NULL;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!d->assembly, LOC_FMT "*ELEMENT in an assembly is not supported: elements belong to parts", KLOC(d));
  PetscCall(ParamRequired(d, "TYPE", &tname));
  /* a conventional shell (S8RT, SAX2T) is read with its own nodes and the type it is expanded into (shell.c) */
  PetscCall(TslDeckShellType(tname, &shell, &type, &nn, &what));
  if (!shell) type = TslElementTypeFind(tname);
  USER_CHECK(type < 0 || !TslElementTypeMechanicalOnly(TslElementTypeGet(type)),
             LOC_FMT "unknown element type %s: the dialect has no such coupled type (CalculiX's mechanical %.*s is read with a temperature, "
                     "docs/elements.md)",
             KLOC(d), tname, (int)strlen(tname) - 1, tname);
  if (shell && !d->shell_noted) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          LOC_FMT "note: %s shell elements are expanded into %s through the thickness each (docs/elements.md, "
                                  "\"Conventional shells\")\n",
                          KLOC(d), shell, what));
    d->shell_noted = PETSC_TRUE;
  }
  if (type < 0 && strlen(tname) < 30) {
    /* CalculiX has no separate coupled types: its mechanical elements (C3D8, CPE4, ...) carry a temperature in
     * a coupled temperature-displacement step. The coupled counterpart of the dialect's name + T is the same
     * interpolation and integration with the temperature added, so such a deck is read with it, and told. */
    char coupled[32];
    PetscCall(PetscSNPrintf(coupled, sizeof(coupled), "%sT", tname));
    type = TslElementTypeFind(coupled);
    if (type >= 0 && !d->type_note) PetscCall(PetscCalloc2(TslElementTypeCount(), &d->type_note, TslElementTypeCount(), &d->type_mech));
    if (type >= 0 && !d->type_note[type].line) d->type_note[type] = d->kwloc, d->type_mech[type] = PETSC_TRUE;
  }
  USER_CHECK(type >= 0, LOC_FMT "unknown element type %s (docs/elements.md lists the types)", KLOC(d), tname);
  et = TslElementTypeGet(type);
  if (!shell) nn = et->geom->nnode;
  if (et->pore) d->pore = PETSC_TRUE;
  if (!m->dim && et->geom->dim > 1) m->dim = et->dim; /* a link (DC1D2, DC1D3) takes the model's dimension, 3 if it is alone */
  USER_CHECK(m->dim == et->dim || et->geom->dim == 1 || !m->dim,
             LOC_FMT "element type %s is %" PetscInt_FMT "D but the model already has %" PetscInt_FMT "D elements (mixing is not supported)", KLOC(d),
             et->name, et->dim, m->dim);
  if (elset) {
    char name[TSL_NAME_LEN];
    USER_CHECK(elset[0], LOC_FMT "ELSET= needs a name", KLOC(d));
    PetscCall(Scoped(d, d->kwloc, elset, name));
    PetscCall(SetGet(d, &m->elsets, &m->nelset, name, &iset));
  }
  for (;;) {
    PetscInt id, k;
    PetscCall(DataLine(d, 1 + nn, &got));
    if (!got) break;
    USER_CHECK(d->nfield == 1 + nn, LOC_FMT "element has %" PetscInt_FMT " nodes but type %s needs %" PetscInt_FMT, DLOC(d), d->nfield - 1,
               shell ? shell : et->name, nn);
    PetscCall(FieldId(d, 0, "the element id", &id));
    id += IdShift(d, -1, PETSC_FALSE);
    PetscCall(TslDeckGrow(&m->elem_id, sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_type, sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_line, 2 * sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_ptr, sizeof(PetscInt), m->nelem + 1));
    k = m->elem_ptr[m->nelem];
    for (PetscInt j = 0; j < nn; j++) {
      PetscCall(TslDeckGrow(&m->elem_conn, sizeof(PetscInt), k));
      PetscCall(FieldId(d, 1 + j, "a node id", &m->elem_conn[k]));
      m->elem_conn[k] += IdShift(d, -1, PETSC_TRUE);
      /* a node given twice collapses the element (Abaqus/CAE's triangles and wedges written as quadrilaterals and
       * bricks): the model check accepts it along the element's edges with a positive volume (check.c,
       * CheckCollapsed); a conventional shell's expansion takes its nodes' normals, so no shell repeats one */
      for (PetscInt i = m->elem_ptr[m->nelem]; i < k && shell; i++)
        USER_CHECK(m->elem_conn[i] != m->elem_conn[k],
                   LOC_FMT "element %" PetscInt_FMT " repeats node %" PetscInt_FMT ": collapsed (degenerate) %s elements are not supported", DLOC(d),
                   id, m->elem_conn[k], shell);
      k++;
    }
    m->elem_id[m->nelem]           = id;
    m->elem_type[m->nelem]         = type;
    m->elem_line[2 * m->nelem]     = d->loc.file;
    m->elem_line[2 * m->nelem + 1] = d->loc.line;
    m->elem_ptr[++m->nelem]        = k;
    if (iset >= 0) PetscCall(SetAppend(&m->elsets[iset], id));
  }
  if (iset >= 0) PetscCall(SetFinish(&m->elsets[iset]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *NSET / *ELSET (kind = 0 / 1). */
static PetscErrorCode KwSet(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m    = d->m;
  PetscBool   node = kw->kind == 0 ? PETSC_TRUE : PETSC_FALSE, got;
  TslSet    **sets = node ? &m->nsets : &m->elsets;
  PetscInt   *nset = node ? &m->nnset : &m->nelset, iset;
  PetscBool   gen  = Param(d, "GENERATE") ? PETSC_TRUE : PETSC_FALSE;
  const char *name, *kind = node ? "node" : "element", *inst = Param(d, "INSTANCE");
  PetscInt    instance = -1, shift;
  char        scoped[TSL_NAME_LEN];

  PetscFunctionBeginUser;
  PetscCall(ParamRequired(d, node ? "NSET" : "ELSET", &name));
  if (inst) { /* an assembly's set of one instance's ids (the part's own numbering) */
    USER_CHECK(d->assembly && d->instance < 0, LOC_FMT "INSTANCE= belongs to a set in an *ASSEMBLY", KLOC(d));
    instance = InstanceFind(d, inst);
    USER_CHECK(instance >= 0, LOC_FMT "INSTANCE=%s: no such instance", KLOC(d), inst);
  }
  shift = IdShift(d, instance, node);
  PetscCall(Scoped(d, d->kwloc, name, scoped));
  PetscCall(SetGet(d, sets, nset, scoped, &iset));
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    if (gen) {
      PetscInt first, last, inc = 1;
      USER_CHECK(d->nfield >= 2 && d->nfield <= 3, LOC_FMT "GENERATE data line needs: first, last[, increment]", DLOC(d));
      PetscCall(FieldId(d, 0, "the first id", &first));
      PetscCall(FieldId(d, 1, "the last id", &last));
      if (d->nfield > 2) PetscCall(FieldInt(d, 2, "the increment", &inc));
      USER_CHECK(inc > 0 && first <= last, LOC_FMT "GENERATE needs first <= last and a positive increment", DLOC(d));
      first += shift, last += shift;
      /* ids must exist by the end of the read: a range wider than the ids defined so far (or than a
       * million before any exist) is a typo, and would otherwise exhaust the memory before saying so */
      {
        PetscInt defined = node ? m->nnode : m->nelem, count = (last - first) / inc + 1;
        USER_CHECK(count <= PetscMax(defined, 1000000),
                   LOC_FMT "GENERATE gives %" PetscInt_FMT " ids, more than the %" PetscInt_FMT " %ss defined so far", DLOC(d), count, defined, kind);
      }
      for (PetscInt id = first; id <= last; id += inc) {
        PetscCall(SetAppend(&(*sets)[iset], id));
        if (id > last - inc) break; /* id + inc would pass last, or overflow near the largest id */
      }
      continue;
    }
    for (PetscInt i = 0; i < d->nfield; i++) {
      const char *f = d->field[i];
      PetscInt    id, src = -1;
      if (!f[0]) continue;
      if (IsInteger(f)) {
        PetscCall(DeckId(d, f, "an id", &id));
        PetscCall(SetAppend(&(*sets)[iset], id + shift));
        continue;
      }
      PetscCall(Scoped(d, d->loc, f, scoped));
      src = node ? TslModelFindNodeSet(m, scoped) : TslModelFindElementSet(m, scoped);
      USER_CHECK(src >= 0, LOC_FMT "undefined %s set %s", DLOC(d), kind, f);
      for (PetscInt k = 0, n = (*sets)[src].n; k < n; k++) PetscCall(SetAppend(&(*sets)[iset], (*sets)[src].ids[k]));
    }
  }
  PetscCall(SetFinish(&(*sets)[iset]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Face label "<prefix>1".."<prefix>6" -> 1..6; the bare prefix -> 0 (surface form); a conventional shell's
 * sides "<prefix>POS" / "<prefix>NEG" -> TSL_FACE_POS / TSL_FACE_NEG (shell.c maps them); anything else -> -1. */
static PetscInt FaceLabel(const char *s, char prefix)
{
  if (toupper((unsigned char)s[0]) != prefix) return -1;
  if (!s[1]) return 0;
  if (s[1] >= '1' && s[1] <= '6' && !s[2]) return s[1] - '0';
  if (prefix != 'P' && TslDeckNameEqual(s + 1, "POS")) return TSL_FACE_POS;
  if (prefix != 'P' && TslDeckNameEqual(s + 1, "NEG")) return TSL_FACE_NEG;
  return -1;
}

static PetscErrorCode SurfaceAppend(TslSurface *s, PetscInt id, PetscInt face)
{
  PetscFunctionBeginUser;
  PetscCall(TslDeckGrow(&s->elem, sizeof(PetscInt), s->n));
  if (s->kind == TSL_SURFACE_ELEMENT) {
    PetscCall(TslDeckGrow(&s->face, sizeof(PetscInt), s->n));
    s->face[s->n] = face;
  }
  s->elem[s->n++] = id;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwSurface(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m = d->m;
  const char *name, *type;
  char        tbuf[32], scoped[TSL_NAME_LEN];
  TslSurface *s;
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(ParamRequired(d, "NAME", &name));
  PetscCall(Scoped(d, d->kwloc, name, scoped));
  USER_CHECK(TslModelFindSurface(m, scoped) < 0, LOC_FMT "surface %s is defined twice", KLOC(d), name);
  type = ParamUpper(d, "TYPE", tbuf, sizeof(tbuf));
  USER_CHECK(!type || !strcmp(type, "ELEMENT") || !strcmp(type, "NODE"), LOC_FMT "*SURFACE, TYPE=%s is not supported (ELEMENT or NODE)", KLOC(d),
             type);
  PetscCall(TslDeckGrow(&m->surfaces, sizeof(TslSurface), m->nsurface));
  s = &m->surfaces[m->nsurface++];
  PetscCall(CopyName(d, d->kwloc, s->name, scoped));
  s->kind = (type && !strcmp(type, "NODE")) ? TSL_SURFACE_NODE : TSL_SURFACE_ELEMENT;
  s->loc  = d->kwloc;
  for (;;) {
    const char *t;
    PetscInt    face = 0, id;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    t = d->field[0];
    if (s->kind == TSL_SURFACE_ELEMENT) {
      USER_CHECK(d->nfield == 2, LOC_FMT "element surface data line needs: element or element set, face label (S1..S6)", DLOC(d));
      face = FaceLabel(d->field[1], 'S');
      USER_CHECK(face > 0, LOC_FMT "bad face label '%s' (expected S1..S6, or SPOS / SNEG on shells)", DLOC(d), d->field[1]);
    } else {
      PetscReal w;
      USER_CHECK(d->nfield >= 1 && d->nfield <= 2, LOC_FMT "node surface data line needs: node or node set[, weight]", DLOC(d));
      if (d->nfield == 2) PetscCall(FieldReal(d, 1, "the weight", &w));
    }
    if (IsInteger(t)) {
      PetscCall(DeckId(d, t, "an id", &id));
      PetscCall(SurfaceAppend(s, id + IdShift(d, -1, s->kind == TSL_SURFACE_NODE), face));
    } else {
      PetscInt src;
      PetscCall(Scoped(d, d->loc, t, scoped));
      src = s->kind == TSL_SURFACE_ELEMENT ? TslModelFindElementSet(m, scoped) : TslModelFindNodeSet(m, scoped);
      USER_CHECK(src >= 0, LOC_FMT "undefined %s set %s", DLOC(d), s->kind == TSL_SURFACE_ELEMENT ? "element" : "node", t);
      const TslSet *set = s->kind == TSL_SURFACE_ELEMENT ? &m->elsets[src] : &m->nsets[src];
      for (PetscInt k = 0; k < set->n; k++) PetscCall(SurfaceAppend(s, set->ids[k], face));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- materials and sections ------------------------------------------------------------------ */

static PetscErrorCode KwMaterial(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m = d->m;
  const char *name;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(ParamRequired(d, "NAME", &name));
  USER_CHECK(TslModelFindMaterial(m, name) < 0, LOC_FMT "material %s is defined twice", KLOC(d), name);
  PetscCall(TslDeckGrow(&m->materials, sizeof(TslMaterial), m->nmaterial));
  PetscCall(CopyName(d, d->kwloc, m->materials[m->nmaterial].name, name));
  m->materials[m->nmaterial].loc = d->kwloc;
  d->material                    = m->nmaterial++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckIsotropic(Deck *d)
{
  char        buf[32];
  const char *t = ParamUpper(d, "TYPE", buf, sizeof(buf));

  PetscFunctionBeginUser;
  USER_CHECK(!t || !strcmp(t, "ISO") || !strcmp(t, "ISOTROPIC"), LOC_FMT "*%s, TYPE=%s is not supported (only ISOTROPIC)", KLOC(d), d->kw, t);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Material properties, one row per keyword (the keyword table's kind indexes it): the values of its
 * data line, where they go in TslMaterial, and the open interval each must lie in. The ranges are the
 * physical ones (a negative density gives temperatures of the wrong sign, not an error, further on), so
 * they are checked here, at the data line. */
/* Material properties, one row per keyword (the keyword table's kind is a TslProperty): the values of a
 * data line and the open interval each must lie in. The ranges are the physical ones (a negative density
 * gives temperatures of the wrong sign, not an error, further on), so they are checked here, at the data
 * line. */
typedef struct {
  const char *what;   /* the value, for messages */
  PetscReal   lo, hi; /* open interval */
  const char *range;  /* the interval as the user reads it */
} DeckPropertyValue;

typedef struct {
  PetscInt          nval;
  DeckPropertyValue val[2];
  PetscBool         isotropic; /* TYPE= may be given, only ISOTROPIC is supported */
} DeckProperty;

static const DeckProperty Properties[TSL_NPROP] = {
    [TSL_PROP_ELASTIC]       = {2,
                                {{"Young's modulus", 0, PETSC_MAX_REAL, "must be positive"}, {"Poisson's ratio", -1, 0.5, "must lie in (-1, 0.5)"}},
                                PETSC_TRUE},
    [TSL_PROP_CONDUCTIVITY]  = {1, {{"the conductivity", 0, PETSC_MAX_REAL, "must be positive"}}, PETSC_TRUE},
    [TSL_PROP_DENSITY]       = {1, {{"the density", 0, PETSC_MAX_REAL, "must be positive"}}, PETSC_FALSE},
    [TSL_PROP_SPECIFIC_HEAT] = {1, {{"the specific heat", 0, PETSC_MAX_REAL, "must be positive"}}, PETSC_FALSE},
    [TSL_PROP_EXPANSION]     = {1, {{"the expansion coefficient", -PETSC_MAX_REAL, PETSC_MAX_REAL, ""}}, PETSC_TRUE},
};

/* The data lines of a material property: one line (a constant; a temperature column is then ignored) or
 * several, each with its temperature, strictly ascending (a table in temperature). */
static PetscErrorCode PropertyLines(Deck *d, const DeckProperty *p, const char *material, TslPropertyTable *tab)
{
  PetscBool got, has_theta, first_has_theta = PETSC_FALSE;
  char      kwname[64];

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(kwname, d->kw, sizeof(kwname)));
  tab->n   = 0;
  tab->loc = d->kwloc;
  while (PETSC_TRUE) {
    PetscInt r = tab->n;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(r < TSL_MAX_TABLE_ROWS, LOC_FMT "*%s: at most %d temperature points", DLOC(d), kwname, TSL_MAX_TABLE_ROWS);
    USER_CHECK(d->nfield <= p->nval + 1,
               LOC_FMT "*%s data line has %" PetscInt_FMT " values, expected %" PetscInt_FMT " (and an optional temperature)", DLOC(d), kwname,
               d->nfield, p->nval);
    for (PetscInt i = 0; i < p->nval; i++) {
      const DeckPropertyValue *pv = &p->val[i];
      PetscCall(FieldReal(d, i, pv->what, &tab->value[r][i]));
      USER_CHECK(tab->value[r][i] > pv->lo && tab->value[r][i] < pv->hi, LOC_FMT "material %s: %s %s (got %g)", DLOC(d), material, pv->what,
                 pv->range, (double)tab->value[r][i]);
    }
    has_theta     = d->nfield > p->nval && d->field[p->nval][0];
    tab->theta[r] = 0;
    if (has_theta) {
      PetscCall(FieldReal(d, p->nval, "the temperature", &tab->theta[r]));
    }
    if (r == 0) first_has_theta = has_theta;
    USER_CHECK(r == 0 || (has_theta && first_has_theta), LOC_FMT "*%s: a temperature-dependent table needs the temperature on every data line",
               DLOC(d), kwname);
    USER_CHECK(r == 0 || tab->theta[r] > tab->theta[r - 1], LOC_FMT "*%s: temperatures must ascend (%g after %g)", DLOC(d), kwname,
               (double)tab->theta[r], (double)tab->theta[r - 1]);
    tab->n++;
  }
  USER_CHECK(tab->n > 0, LOC_FMT "*%s needs a data line", KLOC(d), kwname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwProperty(Deck *d, const DeckKeyword *kw)
{
  TslMaterial        *mat = &d->m->materials[d->material];
  const DeckProperty *p   = &Properties[kw->kind];

  PetscFunctionBeginUser;
  if (p->isotropic) PetscCall(CheckIsotropic(d));
  if (kw->kind == TSL_PROP_EXPANSION) PetscCall(ParamReal(d, "ZERO", &mat->alpha_zero, NULL));
  PetscCall(PropertyLines(d, p, mat->name, &mat->prop[kw->kind]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A yield-surface size table "yield stress, plastic strain[, temperature]" (*PLASTIC, HARDENING=ISOTROPIC, and
 * *CYCLIC HARDENING's table; TslPlasticTable). For each temperature the curve starts at plastic strain 0 and its
 * strains ascend; the temperatures ascend from one curve to the next; every line gives a temperature or none does. */
static PetscErrorCode PlasticCurve(Deck *d, TslMaterial *mat, TslPlasticTable *t)
{
  PetscBool got, first_theta = PETSC_FALSE;

  PetscFunctionBeginUser;
  t->n = 0;
  for (;;) {
    PetscReal     *r;
    PetscBool      theta;
    const PetscInt n = t->n;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(n < TSL_MAX_TABLE_ROWS, LOC_FMT "*%s: at most %d data lines", DLOC(d), d->kw, TSL_MAX_TABLE_ROWS);
    USER_CHECK(d->nfield >= 1 && d->nfield <= 3, LOC_FMT "*%s data line needs: yield stress, plastic strain[, temperature]", DLOC(d), d->kw);
    r = t->row[n];
    PetscCall(FieldReal(d, 0, "the yield stress", &r[0]));
    PetscCall(FieldRealDefault(d, 1, "the plastic strain", 0.0, &r[1]));
    theta = d->nfield > 2 && d->field[2][0] ? PETSC_TRUE : PETSC_FALSE;
    r[2]  = 0;
    if (theta) PetscCall(FieldReal(d, 2, "the temperature", &r[2]));
    if (!n) first_theta = theta;
    USER_CHECK(theta == first_theta, LOC_FMT "*%s: a temperature-dependent table needs the temperature on every data line", DLOC(d), d->kw);
    USER_CHECK(r[0] > 0, LOC_FMT "material %s: *%s: the yield stress must be positive (got %g)", DLOC(d), mat->name, d->kw, (double)r[0]);
    USER_CHECK(r[1] >= 0, LOC_FMT "material %s: *%s: the plastic strain must not be negative (got %g)", DLOC(d), mat->name, d->kw, (double)r[1]);
    if (!n || r[2] != t->row[n - 1][2]) { /* the first point of a temperature's curve */
      USER_CHECK(!n || r[2] > t->row[n - 1][2], LOC_FMT "*%s: temperatures must ascend from one curve to the next (%g after %g)", DLOC(d), d->kw,
                 (double)r[2], (double)t->row[n - 1][2]);
      USER_CHECK(r[1] == 0, LOC_FMT "*%s: the first yield point%s must be at plastic strain 0 (got %g)", DLOC(d), d->kw,
                 theta ? " of each temperature" : "", (double)r[1]);
    } else
      USER_CHECK(r[1] > t->row[n - 1][1], LOC_FMT "*%s: the plastic strains must ascend (%g after %g)", DLOC(d), d->kw, (double)r[1],
                 (double)t->row[n - 1][1]);
    t->n++;
  }
  USER_CHECK(t->n > 0, LOC_FMT "*%s needs a data line", KLOC(d), d->kw);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One record of want reals (blank: 0) from data lines of at most 8 fields each, as the dialect continues a long
 * record on the next line; *nrec: the fields given (want - 1 when the trailing temperature is left off). got = FALSE
 * at the keyword's end. */
static PetscErrorCode DataRecord(Deck *d, PetscInt want, PetscReal v[], PetscInt *nrec, TslLoc *loc, PetscBool *got)
{
  PetscInt have = 0;

  PetscFunctionBeginUser;
  PetscCall(DataLine(d, 0, got));
  if (!*got) PetscFunctionReturn(PETSC_SUCCESS);
  *loc = d->loc;
  for (;;) {
    PetscBool more;
    USER_CHECK(have + d->nfield <= want, LOC_FMT "*%s: a data record here has at most %" PetscInt_FMT " values (got %" PetscInt_FMT ")", DLOC(d), d->kw,
               want, have + d->nfield);
    for (PetscInt i = 0; i < d->nfield; i++) PetscCall(FieldRealDefault(d, i, "a value", 0.0, &v[have + i]));
    have += d->nfield;
    if (have >= want - 1 || d->nfield < 8) break; /* complete (the temperature may be left off), or a short line ends it */
    PetscCall(DataLine(d, 0, &more));
    USER_CHECK(more, LOC_FMT "*%s: the data record ends after %" PetscInt_FMT " of its %" PetscInt_FMT " values", KLOC(d), d->kw, have, want - 1);
  }
  for (PetscInt i = have; i < want; i++) v[i] = 0;
  *nrec = have;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *PLASTIC (Mises plasticity; TslPlasticTable). HARDENING=ISOTROPIC (the dialect's default): the curve of
 * PlasticCurve. HARDENING=KINEMATIC: linear kinematic hardening, two lines at most per temperature (the dialect's: the
 * slope between them is the back stress's modulus). HARDENING=COMBINED, DATA TYPE=PARAMETERS: "sigma_0, C_1, gamma_1,
 * ..., C_n, gamma_n[, temperature]" with n = NUMBER BACKSTRESSES (default 1), one record or one per temperature; the
 * surface's size sigma_0 unless a *CYCLIC HARDENING follows. The other data types, rate
 * dependence and the other hardening laws are refused (docs/keywords.md). */
static PetscErrorCode KwPlastic(Deck *d, const DeckKeyword *kw)
{
  TslMaterial     *mat = &d->m->materials[d->material];
  TslPlasticTable *t   = &mat->plastic;
  char             hb[32], db[32];
  const char      *hard = ParamUpper(d, "HARDENING", hb, sizeof(hb)), *dtype = ParamUpper(d, "DATA TYPE", db, sizeof(db));

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!hard || !strcmp(hard, "ISOTROPIC") || !strcmp(hard, "KINEMATIC") || !strcmp(hard, "COMBINED"),
             LOC_FMT "*PLASTIC, HARDENING=%s is not supported yet (ISOTROPIC, KINEMATIC and COMBINED: Mises yield with isotropic, linear kinematic or "
                     "nonlinear kinematic hardening)",
             KLOC(d), hard);
  USER_CHECK(!Param(d, "RATE"), LOC_FMT "*PLASTIC, RATE= (rate-dependent yield curves) is not supported yet", KLOC(d));
  USER_CHECK(!t->n && !t->nvoce, LOC_FMT "material %s: a second *PLASTIC (the first at line %" PetscInt_FMT ")", KLOC(d), mat->name, t->loc.line);
  USER_CHECK(!dtype || (hard && !strcmp(hard, "COMBINED")), LOC_FMT "*PLASTIC: DATA TYPE= belongs to HARDENING=COMBINED", KLOC(d));
  USER_CHECK(!Param(d, "NUMBER BACKSTRESSES") || (hard && !strcmp(hard, "COMBINED")), LOC_FMT "*PLASTIC: NUMBER BACKSTRESSES= belongs to HARDENING=COMBINED",
             KLOC(d));
  t->loc = d->kwloc;
  if (hard && !strcmp(hard, "COMBINED")) {
    PetscInt  nb = 1, nrec = 0;
    PetscReal v[2 * TSL_MAX_BACKSTRESS + 2];
    TslLoc    at;
    PetscBool got;
    USER_CHECK(dtype && !strcmp(dtype, "PARAMETERS"),
               LOC_FMT "*PLASTIC, HARDENING=COMBINED, DATA TYPE=%s is not supported yet: give the nonlinear kinematic law's parameters (DATA TYPE=PARAMETERS: "
                       "yield stress, C_1, gamma_1, ...; CalculiX reads such a table as a multilinear kinematic curve, Abaqus fits the parameters to it)",
               KLOC(d), dtype ? dtype : "HALF CYCLE (the default)");
    PetscCall(ParamInt(d, "NUMBER BACKSTRESSES", &nb));
    USER_CHECK(nb >= 1 && nb <= TSL_MAX_BACKSTRESS, LOC_FMT "*PLASTIC: NUMBER BACKSTRESSES must lie in 1..%d (got %" PetscInt_FMT ")", KLOC(d),
               TSL_MAX_BACKSTRESS, nb);
    for (PetscInt r = 0;; r++) { /* one record per temperature, ascending */
      PetscCall(DataRecord(d, 2 * nb + 2, v, &nrec, &at, &got));
      if (!got) break;
      d->loc = at;
      USER_CHECK(r < TSL_MAX_TABLE_ROWS, LOC_FMT "*PLASTIC: at most %d data records", DLOC(d), TSL_MAX_TABLE_ROWS);
      USER_CHECK(nrec >= 2 * nb + 1, LOC_FMT "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS with %" PetscInt_FMT " back stress%s needs: yield stress, then C and gamma of each "
                 "(%" PetscInt_FMT " values)[, temperature] (got %" PetscInt_FMT ")", DLOC(d), nb, nb > 1 ? "es" : "", 2 * nb + 1, nrec);
      USER_CHECK(v[0] > 0, LOC_FMT "material %s: *PLASTIC: the yield stress must be positive (got %g)", DLOC(d), mat->name, (double)v[0]);
      USER_CHECK(!r || nrec == 2 * nb + 2, LOC_FMT "*PLASTIC, HARDENING=COMBINED: temperature-dependent parameters need the temperature on every record", DLOC(d));
      USER_CHECK(!r || v[2 * nb + 1] > t->kt_theta[r - 1], LOC_FMT "*PLASTIC: the records' temperatures must ascend (%g after %g)", DLOC(d), (double)v[2 * nb + 1],
                 (double)t->kt_theta[r - 1]);
      for (PetscInt k = 0; k < nb; k++) {
        USER_CHECK(v[1 + 2 * k] >= 0 && v[2 + 2 * k] >= 0, LOC_FMT "material %s: *PLASTIC: back stress %" PetscInt_FMT ": C and gamma must not be negative (got %g, %g)",
                   DLOC(d), mat->name, k + 1, (double)v[1 + 2 * k], (double)v[2 + 2 * k]);
        t->kt_C[r][k] = v[1 + 2 * k], t->kt_gamma[r][k] = v[2 + 2 * k];
      }
      t->kt_theta[r] = v[2 * nb + 1];
      t->row[r][0] = v[0], t->row[r][1] = 0, t->row[r][2] = v[2 * nb + 1]; /* the surface's size at each temperature, until a *CYCLIC HARDENING */
      t->n = r + 1;
    }
    USER_CHECK(t->n > 0, LOC_FMT "*PLASTIC needs a data line", KLOC(d));
    if (t->n == 1) t->kt_theta[0] = t->row[0][2] = 0; /* one record: no temperature dependence */
    t->nback = nb, t->combined = PETSC_TRUE, t->nkt = t->n;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PlasticCurve(d, mat, t));
  if (hard && !strcmp(hard, "KINEMATIC")) { /* per temperature: the yield stress at 0 and, from a second point, the back stress's modulus */
    PetscInt ng = 0;
    for (PetscInt i = 0; i < t->n;) {
      PetscInt e = i + 1;
      while (e < t->n && t->row[e][2] == t->row[i][2]) e++;
      USER_CHECK(e - i <= 2, LOC_FMT "*PLASTIC, HARDENING=KINEMATIC takes two data lines per temperature (linear kinematic hardening; got %" PetscInt_FMT " at %g)",
                 KLOC(d), e - i, (double)t->row[i][2]);
      USER_CHECK(e - i < 2 || t->row[i + 1][0] >= t->row[i][0],
                 LOC_FMT "material %s: *PLASTIC, HARDENING=KINEMATIC: the second yield stress must not be below the first (%g after %g)", KLOC(d), mat->name,
                 (double)t->row[i + 1][0], (double)t->row[i][0]);
      t->kt_C[ng][0]     = e - i == 2 ? (t->row[i + 1][0] - t->row[i][0]) / t->row[i + 1][1] : 0;
      t->kt_gamma[ng][0] = 0;
      t->kt_theta[ng]    = t->row[i][2];
      t->row[ng][0] = t->row[i][0], t->row[ng][1] = 0, t->row[ng][2] = t->row[i][2]; /* the surface's size at the temperature */
      ng++, i = e;
    }
    t->n = ng, t->nback = 1, t->nkt = ng; /* Ziegler-Prager: the nonlinear law with gamma = 0 */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *CYCLIC HARDENING (after *PLASTIC, HARDENING=COMBINED): the yield surface's size against the equivalent plastic
 * strain, as a table (PlasticCurve) or, with PARAMETERS, "sigma_0, Q_inf, b[, temperature]" lines (ascending
 * temperatures) of sigma_0 + Q_inf (1 - exp(-b p)). */
static PetscErrorCode KwCyclicHardening(Deck *d, const DeckKeyword *kw)
{
  TslMaterial     *mat = &d->m->materials[d->material];
  TslPlasticTable *t   = &mat->plastic;
  PetscBool        got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(t->combined, LOC_FMT "material %s: *CYCLIC HARDENING belongs after *PLASTIC, HARDENING=COMBINED%s", KLOC(d), mat->name,
             t->n ? " (this material's *PLASTIC has another hardening)" : "");
  USER_CHECK(!t->cyclic_loc.line, LOC_FMT "material %s: a second *CYCLIC HARDENING (the first at line %" PetscInt_FMT ")", KLOC(d), mat->name, t->cyclic_loc.line);
  t->cyclic_loc = d->kwloc;
  if (!Param(d, "PARAMETERS")) PetscFunctionReturn(PlasticCurve(d, mat, t));
  t->n = 0, t->nvoce = 0;
  for (;;) {
    PetscReal *r;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(t->nvoce < TSL_MAX_TABLE_ROWS, LOC_FMT "*CYCLIC HARDENING: at most %d data lines", DLOC(d), TSL_MAX_TABLE_ROWS);
    USER_CHECK(d->nfield >= 1 && d->nfield <= 4, LOC_FMT "*CYCLIC HARDENING, PARAMETERS data line needs: yield stress, Q_inf, b[, temperature]", DLOC(d));
    r = t->voce[t->nvoce];
    PetscCall(FieldReal(d, 0, "the yield stress", &r[0]));
    PetscCall(FieldRealDefault(d, 1, "Q_inf", 0.0, &r[1]));
    PetscCall(FieldRealDefault(d, 2, "b", 0.0, &r[2]));
    PetscCall(FieldRealDefault(d, 3, "the temperature", 0.0, &r[3]));
    USER_CHECK(r[0] > 0, LOC_FMT "material %s: *CYCLIC HARDENING: the yield stress must be positive (got %g)", DLOC(d), mat->name, (double)r[0]);
    USER_CHECK(r[2] >= 0, LOC_FMT "material %s: *CYCLIC HARDENING: b must not be negative (got %g)", DLOC(d), mat->name, (double)r[2]);
    USER_CHECK(r[0] + r[1] > 0, LOC_FMT "material %s: *CYCLIC HARDENING: the saturated size yield stress + Q_inf must be positive (got %g)", DLOC(d), mat->name,
               (double)(r[0] + r[1]));
    USER_CHECK(!t->nvoce || r[3] > t->voce[t->nvoce - 1][3], LOC_FMT "*CYCLIC HARDENING: the temperatures must ascend (%g after %g)", DLOC(d), (double)r[3],
               (double)t->voce[t->nvoce - 1][3]);
    t->nvoce++;
  }
  USER_CHECK(t->nvoce > 0, LOC_FMT "*CYCLIC HARDENING needs a data line", KLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *INELASTIC HEAT FRACTION: the share eta of the plastic work that turns into heat (default 0.9, in [0, 1]). */
static PetscErrorCode KwInelasticHeatFraction(Deck *d, const DeckKeyword *kw)
{
  TslMaterial *mat = &d->m->materials[d->material];
  PetscBool    got;

  PetscFunctionBeginUser;
  (void)kw;
  mat->heat_fraction     = 0.9;
  mat->heat_fraction_loc = d->kwloc;
  PetscCall(DataLine(d, 0, &got));
  if (got) {
    USER_CHECK(d->nfield == 1, LOC_FMT "*INELASTIC HEAT FRACTION data line needs one value, the fraction", DLOC(d));
    PetscCall(FieldRealDefault(d, 0, "the fraction", 0.9, &mat->heat_fraction));
    USER_CHECK(mat->heat_fraction >= 0 && mat->heat_fraction <= 1, LOC_FMT "*INELASTIC HEAT FRACTION must lie in [0, 1] (got %g)", DLOC(d),
               (double)mat->heat_fraction);
    PetscCall(DataLine(d, 0, &got));
    USER_CHECK(!got, LOC_FMT "*INELASTIC HEAT FRACTION takes one data line", DLOC(d));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *DAMPING, ALPHA=, BETA= (a material option; no data lines): Rayleigh damping of the material, mass-proportional alpha
 * (1/time) and stiffness-proportional beta (time). Explicit steps apply it (docs/explicit.md "Damping"); the other steps
 * have no inertia, so it has no effect there, as in the dialect. COMPOSITE= and STRUCTURAL= (the steady-state dynamics
 * forms) are refused. */
static PetscErrorCode KwDamping(Deck *d, const DeckKeyword *kw)
{
  TslMaterial *mat = &d->m->materials[d->material];
  PetscBool    a = PETSC_FALSE, b = PETSC_FALSE, got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!Param(d, "STRUCTURAL") && !Param(d, "COMPOSITE"),
             LOC_FMT "*DAMPING, STRUCTURAL= and COMPOSITE= (steady-state dynamics) are not supported: give ALPHA= and BETA= (Rayleigh damping)", KLOC(d));
  USER_CHECK(mat->damping_loc.line == 0, LOC_FMT "*DAMPING is given twice in material %s", KLOC(d), mat->name);
  PetscCall(ParamReal(d, "ALPHA", &mat->damp_alpha, &a));
  PetscCall(ParamReal(d, "BETA", &mat->damp_beta, &b));
  USER_CHECK(a || b, LOC_FMT "*DAMPING needs ALPHA= (mass-proportional, 1/time) or BETA= (stiffness-proportional, time)", KLOC(d));
  USER_CHECK(mat->damp_alpha >= 0 && mat->damp_beta >= 0, LOC_FMT "*DAMPING, ALPHA= and BETA= must not be negative (got %g, %g)", KLOC(d),
             (double)mat->damp_alpha, (double)mat->damp_beta);
  mat->damping_loc = d->kwloc;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*DAMPING takes no data lines (ALPHA= and BETA= are parameters)", DLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *RATE DEPENDENT (after *PLASTIC): the yield stress's rate factor, TYPE=POWER LAW (the default; "D, n") or JOHNSON
 * COOK ("C, rate_0"), one data line (temperature dependence and TYPE=YIELD RATIO: not yet). */
static PetscErrorCode KwRateDependent(Deck *d, const DeckKeyword *kw)
{
  TslMaterial     *mat = &d->m->materials[d->material];
  TslPlasticTable *t   = &mat->plastic;
  char             tb[32];
  const char      *type = ParamUpper(d, "TYPE", tb, sizeof(tb));
  PetscBool        got;
  PetscReal        a, b;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(TslMaterialIsPlastic(mat), LOC_FMT "material %s: *RATE DEPENDENT belongs after the material's *PLASTIC", KLOC(d), mat->name);
  USER_CHECK(!t->rate_law, LOC_FMT "material %s: a second *RATE DEPENDENT (the first at line %" PetscInt_FMT ")", KLOC(d), mat->name, t->rate_loc.line);
  USER_CHECK(!type || !strcmp(type, "POWER LAW") || !strcmp(type, "JOHNSON COOK"),
             LOC_FMT "*RATE DEPENDENT, TYPE=%s is not supported yet (POWER LAW and JOHNSON COOK are)", KLOC(d), type);
  t->rate_loc = d->kwloc;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*RATE DEPENDENT needs a data line", KLOC(d));
  USER_CHECK(d->nfield >= 2 && d->nfield <= 3, LOC_FMT "*RATE DEPENDENT data line needs: %s[, temperature]", DLOC(d),
             type && !strcmp(type, "JOHNSON COOK") ? "C, the reference strain rate" : "D, n");
  PetscCall(FieldReal(d, 0, type && !strcmp(type, "JOHNSON COOK") ? "C" : "D", &a));
  PetscCall(FieldReal(d, 1, type && !strcmp(type, "JOHNSON COOK") ? "the reference strain rate" : "n", &b));
  if (type && !strcmp(type, "JOHNSON COOK")) {
    USER_CHECK(a >= 0 && b > 0, LOC_FMT "material %s: *RATE DEPENDENT, TYPE=JOHNSON COOK needs C >= 0 and a positive reference strain rate (got %g, %g)", DLOC(d),
               mat->name, (double)a, (double)b);
    t->rate_law = 2;
  } else {
    USER_CHECK(a > 0 && b > 0, LOC_FMT "material %s: *RATE DEPENDENT, TYPE=POWER LAW needs D > 0 and n > 0 (got %g, %g)", DLOC(d), mat->name, (double)a,
               (double)b);
    t->rate_law = 1;
  }
  t->rate[0] = a, t->rate[1] = b;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*RATE DEPENDENT with temperature-dependent data (a second data line) is not supported yet", DLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A new section from ELSET= and MATERIAL= (both keywords). */
static PetscErrorCode NewSection(Deck *d, TslSection **sp)
{
  TslModel   *m = d->m;
  const char *elset, *mat;
  TslSection *s;

  PetscFunctionBeginUser;
  PetscCall(ParamRequired(d, "ELSET", &elset));
  PetscCall(ParamRequired(d, "MATERIAL", &mat));
  PetscCall(TslDeckGrow(&m->sections, sizeof(TslSection), m->nsection));
  s = &m->sections[m->nsection++];
  PetscCall(PetscMemzero(s, sizeof(*s)));
  PetscCall(Scoped(d, d->kwloc, elset, s->elset));
  PetscCall(CopyName(d, d->kwloc, s->material, mat));
  s->material_index  = -1;
  s->thickness       = 1.0;
  s->loc             = d->kwloc;
  s->ref_node.id     = -1;
  *sp                = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwSolidSection(Deck *d, const DeckKeyword *kw)
{
  TslSection *s;
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(NewSection(d, &s));
  {
    const char *ref = Param(d, "REF NODE");
    if (ref) {
      USER_CHECK(ref[0], LOC_FMT "REF NODE= needs a node or a node set", KLOC(d));
      if (IsInteger(ref)) {
        PetscCall(DeckId(d, ref, "the reference node", &s->ref_node.id));
        s->ref_node.id += IdShift(d, -1, PETSC_TRUE);
      } else
        PetscCall(Scoped(d, d->kwloc, ref, s->ref_node.set));
    }
  }
  PetscCall(DataLine(d, 0, &got));
  if (got) {
    USER_CHECK(d->nfield <= 1, LOC_FMT "*SOLID SECTION data line needs only the thickness", DLOC(d));
    PetscCall(FieldRealDefault(d, 0, "the thickness", 1.0, &s->thickness));
    USER_CHECK(s->thickness > 0, LOC_FMT "the thickness must be positive", DLOC(d));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *SHELL SECTION for continuum shells (SC8RT, SC6RT): the thickness comes from the nodes, so the data
 * line's thickness is checked and otherwise ignored, as are OFFSET= and NODAL THICKNESS (the dialect ignores
 * them for continuum shells). Conventional shells (S8RT, SAX2T) take the data line's thickness, or with NODAL
 * THICKNESS each node's from *NODAL THICKNESS, and OFFSET=
 * (SPOS, SNEG or a fraction of the thickness; shell.c accepts -0.5, 0 and 0.5). Its second field is the number of Simpson points through the
 * thickness (odd, 3 to 15, default 5). STACK DIRECTION=1, 2 or 3 (the element's own reference direction along the thickness; 3, from face 1 to face
 * 2, by default; not ORIENTATION) and SECTION INTEGRATION=SIMPSON (Gauss is not allowed for coupled shells in the dialect either). */
static PetscErrorCode KwShellSection(Deck *d, const DeckKeyword *kw)
{
  TslSection *s;
  PetscBool   got, set;
  char        buf[64];
  const char *v;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(NewSection(d, &s));
  s->shell        = PETSC_TRUE;
  s->shell_points = 5;
  s->shell_stack  = 3;
  PetscCall(ParamReal(d, "THICKNESS MODULUS", &s->thickness_modulus, &set));
  USER_CHECK(!set || s->thickness_modulus > 0, LOC_FMT "THICKNESS MODULUS= must be positive", KLOC(d));
  v = ParamUpper(d, "STACK DIRECTION", buf, sizeof(buf));
  USER_CHECK(!v || !strcmp(v, "1") || !strcmp(v, "2") || !strcmp(v, "3"),
             LOC_FMT "STACK DIRECTION=%s is not supported: 1, 2 or 3 (the element's own direction along the thickness; ORIENTATION is not)", KLOC(d),
             v);
  if (v) s->shell_stack = v[0] - '0';
  v = ParamUpper(d, "SECTION INTEGRATION", buf, sizeof(buf));
  USER_CHECK(!v || !strcmp(v, "SIMPSON"),
             LOC_FMT "SECTION INTEGRATION=%s is not supported: SIMPSON only (the dialect allows no Gauss rule for coupled temperature shells)",
             KLOC(d), v);
  USER_CHECK(!Param(d, "POISSON"), LOC_FMT "POISSON= is not supported: the thickness behaviour is given by THICKNESS MODULUS=", KLOC(d));
  USER_CHECK(!Param(d, "COMPOSITE"), LOC_FMT "COMPOSITE sections are not supported: one material per *SHELL SECTION", KLOC(d));
  USER_CHECK(!Param(d, "DENSITY"), LOC_FMT "DENSITY= (mass per area added to the shell) is not supported: give the material's *DENSITY", KLOC(d));
  s->shell_thickness = 1.0;
  v                  = ParamUpper(d, "OFFSET", buf, sizeof(buf));
  if (v) {
    char *end;
    if (!strcmp(v, "SPOS"))
      s->shell_offset = 0.5;
    else if (!strcmp(v, "SNEG"))
      s->shell_offset = -0.5;
    else {
      s->shell_offset = strtod(v, &end);
      USER_CHECK(v[0] && !*end && (PetscIsNormalReal(s->shell_offset) || s->shell_offset == 0), LOC_FMT "OFFSET=%s: expected SPOS, SNEG or a number",
                 KLOC(d), v);
    }
  }
  PetscCall(DataLine(d, 0, &got));
  if (got) {
    PetscReal t;
    USER_CHECK(d->nfield <= 2, LOC_FMT "*SHELL SECTION data line takes the thickness and the number of integration points", DLOC(d));
    PetscCall(FieldRealDefault(d, 0, "the thickness", 1.0, &t));
    USER_CHECK(t > 0, LOC_FMT "the thickness must be positive", DLOC(d));
    s->shell_thickness = t;
  }
  if (Param(d, "NODAL THICKNESS")) s->shell_thickness = -1; /* conventional shells: the nodes' *NODAL THICKNESS (shell.c) */
  if (got) {
    if (d->nfield > 1 && d->field[1][0]) PetscCall(FieldInt(d, 1, "the number of integration points", &s->shell_points));
    USER_CHECK(s->shell_points >= 3 && s->shell_points <= 15 && s->shell_points % 2 == 1,
               LOC_FMT "the number of integration points through the thickness must be odd, 3 to 15 (Simpson's rule), got %" PetscInt_FMT, DLOC(d),
               s->shell_points);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- other model data ------------------------------------------------------------------------ */

/* An instance's own label "i.n" of a node (element): *id its id here and PETSC_TRUE; PETSC_FALSE if f is not
 * one (a set name may contain dots: "i.name"). */
static PetscErrorCode InstanceLabel(Deck *d, const char *f, PetscBool node, PetscInt *id, PetscBool *is)
{
  const char *dot = strrchr(f, '.');
  char        inst[TSL_NAME_LEN];

  PetscFunctionBeginUser;
  *is = PETSC_FALSE;
  if (!d->ninst || !dot || dot == f || (size_t)(dot - f) >= sizeof(inst) || !IsInteger(dot + 1)) PetscFunctionReturn(PETSC_SUCCESS);
  memcpy(inst, f, (size_t)(dot - f));
  inst[dot - f] = 0;
  {
    const PetscInt i = InstanceFind(d, inst);
    if (i < 0) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCall(DeckId(d, dot + 1, node ? "a node label" : "an element label", id));
    *id += IdShift(d, i, node);
    *is = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A node (node = PETSC_TRUE) or element target: an id, an instance's label "i.n", or a set name; inside a part
 * (*NODAL THICKNESS, the one such keyword a part holds) the part's own id or set name. */
static PetscErrorCode ParseTarget(Deck *d, const char *f, PetscBool node, TslTarget *t)
{
  PetscBool label;

  PetscFunctionBeginUser;
  USER_CHECK(f[0], LOC_FMT "missing node/element or set name", DLOC(d));
  t->set[0] = 0;
  t->id     = -1;
  PetscCall(InstanceLabel(d, f, node, &t->id, &label));
  if (label) PetscFunctionReturn(PETSC_SUCCESS);
  if (IsInteger(f)) {
    PetscCall(DeckId(d, f, "an id", &t->id));
    t->id += IdShift(d, -1, node);
  } else PetscCall(Scoped(d, d->loc, f, t->set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *INITIAL CONDITIONS, TYPE=TEMPERATURE data line: node or node set, temperature. */
static PetscErrorCode InitialTemperatureLine(Deck *d)
{
  TslModel              *m = d->m;
  TslInitialTemperature *it;

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 2, LOC_FMT "*INITIAL CONDITIONS data line needs: node or node set, temperature", DLOC(d));
  PetscCall(TslDeckGrow(&m->init, sizeof(*it), m->ninit));
  it = &m->init[m->ninit++];
  PetscCall(ParseTarget(d, d->field[0], PETSC_TRUE, &it->target));
  PetscCall(FieldReal(d, 1, "the temperature", &it->value));
  it->loc = d->loc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *NODAL THICKNESS data line: node or node set, thickness[, a second thickness (beams in the dialect; not
 * read)]. The thickness of the conventional shells whose *SHELL SECTION has NODAL THICKNESS (shell.c).
 * Model data, or part data as Abaqus/CAE writes it: there the part's own node ids and set names. */
static PetscErrorCode KwNodalThickness(Deck *d, const DeckKeyword *kw)
{
  TslModel          *m = d->m;
  TslNodalThickness *nt;
  PetscBool          got;

  PetscFunctionBeginUser;
  (void)kw;
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield == 2 || d->nfield == 3, LOC_FMT "*NODAL THICKNESS data line needs: node or node set, thickness", DLOC(d));
    PetscCall(TslDeckGrow(&m->nodal_thickness, sizeof(*nt), m->nnodal_thickness));
    nt = &m->nodal_thickness[m->nnodal_thickness++];
    PetscCall(ParseTarget(d, d->field[0], PETSC_TRUE, &nt->target));
    PetscCall(FieldReal(d, 1, "the thickness", &nt->value));
    USER_CHECK(nt->value > 0, LOC_FMT "the thickness must be positive (got %g)", DLOC(d), (double)nt->value);
    nt->loc = d->loc;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *INITIAL CONDITIONS, TYPE=VELOCITY data line: node or node set, dof, velocity (Abaqus and CalculiX). The dof
 * must be a displacement (1..3); whether the model's elements carry it is checked with the whole model
 * (TslModelCheck), since the elements may come later in the deck. */
static PetscErrorCode InitialVelocityLine(Deck *d)
{
  TslModel           *m = d->m;
  TslInitialVelocity *iv;

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 3, LOC_FMT "*INITIAL CONDITIONS, TYPE=VELOCITY data line needs: node or node set, dof (1..3), velocity", DLOC(d));
  PetscCall(TslDeckGrow(&m->vinit, sizeof(*iv), m->nvinit));
  iv = &m->vinit[m->nvinit++];
  PetscCall(ParseTarget(d, d->field[0], PETSC_TRUE, &iv->target));
  PetscCall(FieldInt(d, 1, "the degree of freedom", &iv->dof));
  USER_CHECK(iv->dof >= 1 && iv->dof <= 3, LOC_FMT "an initial velocity needs a displacement degree of freedom 1..3 (got %" PetscInt_FMT ")", DLOC(d),
             iv->dof);
  PetscCall(FieldReal(d, 2, "the velocity", &iv->value));
  iv->loc = d->loc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The TYPE= values of *INITIAL CONDITIONS this reader knows, each with its data-line parser. */
static const struct {
  const char *type;
  PetscErrorCode (*line)(Deck *);
} InitialTypes[] = {
    {"TEMPERATURE", InitialTemperatureLine},
    {"VELOCITY", InitialVelocityLine},
};

/* A keyword's data lines read past, with a warning at its line naming it (what; NULL: the keyword) and why
 * (NULL: no reason given). */
static PetscErrorCode ReadPast(Deck *d, const char *what, const char *why)
{
  PetscBool got;

  PetscFunctionBeginUser;
  if (what)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "warning: %s is ignored%s%s\n", KLOC(d), what, why ? ": " : "", why ? why : ""));
  else
    PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "warning: *%s is ignored%s%s\n", KLOC(d), d->kw, why ? ": " : "", why ? why : ""));
  do PetscCall(DataLine(d, 0, &got));
  while (got);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwInitial(Deck *d, const DeckKeyword *kw)
{
  char        buf[32];
  const char *type = ParamUpper(d, "TYPE", buf, sizeof(buf));
  PetscInt    k    = -1;
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(type && type[0], LOC_FMT "*INITIAL CONDITIONS needs the parameter TYPE=", KLOC(d));
  if (!strcmp(type, "PORE PRESSURE") || !strcmp(type, "RATIO") || !strcmp(type, "SATURATION")) {
    char what[64];
    PetscCall(PetscSNPrintf(what, sizeof(what), "*INITIAL CONDITIONS, TYPE=%s", type));
    PetscCall(ReadPast(d, what, PORE_FLUID_NOTE));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (size_t i = 0; i < sizeof(InitialTypes) / sizeof(InitialTypes[0]); i++)
    if (!strcmp(type, InitialTypes[i].type)) k = (PetscInt)i;
  USER_CHECK(k >= 0, LOC_FMT "*INITIAL CONDITIONS, TYPE=%s is not supported (only TEMPERATURE and VELOCITY)", KLOC(d), type);
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    PetscCall(InitialTypes[k].line(d));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* DEFINITION=PERIODIC, Abaqus's Fourier series: a line "N, omega, t0, A0", then the N pairs "A_k, B_k" over as many
 * lines as they take; a = A0 + sum_k A_k cos(k omega (t - t0)) + B_k sin(k omega (t - t0)) for t >= t0, A0 before. */
static PetscErrorCode AmplitudePeriodic(Deck *d, TslAmplitude *a)
{
  PetscInt  got_terms = 0;
  PetscBool got;

  PetscFunctionBeginUser;
  a->form = TSL_AMP_PERIODIC;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*AMPLITUDE %s, DEFINITION=PERIODIC: expected a line \"N, omega, t0, A0\"", KLOC(d), a->name);
  USER_CHECK(d->nfield >= 2 && d->nfield <= 4, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: the first line holds N, omega, t0, A0 (got %" PetscInt_FMT " values)", DLOC(d), d->nfield);
  PetscCall(FieldInt(d, 0, "the number of terms N", &a->nterm));
  PetscCall(FieldReal(d, 1, "the circular frequency omega", &a->omega));
  PetscCall(FieldRealDefault(d, 2, "the starting time t0", 0, &a->t0));
  PetscCall(FieldRealDefault(d, 3, "the constant term A0", 0, &a->a0));
  USER_CHECK(a->nterm >= 1 && a->nterm <= 1000, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: N must be 1 to 1000 (got %" PetscInt_FMT ")", DLOC(d), a->nterm);
  USER_CHECK(a->omega > 0, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: omega must be > 0 (got %g)", DLOC(d), (double)a->omega);
  PetscCall(PetscCalloc1(a->nterm, &a->cosc));
  PetscCall(PetscCalloc1(a->nterm, &a->sinc));
  while (got_terms < a->nterm) {
    PetscCall(DataLine(d, 0, &got));
    USER_CHECK(got, LOC_FMT "*AMPLITUDE %s, DEFINITION=PERIODIC: N = %" PetscInt_FMT " needs %" PetscInt_FMT " pairs A_k, B_k; the data ends after %" PetscInt_FMT, KLOC(d), a->name,
               a->nterm, a->nterm, got_terms);
    USER_CHECK(d->nfield % 2 == 0, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: the coefficients come in pairs A_k, B_k; got an odd number of values", DLOC(d));
    USER_CHECK(got_terms + d->nfield / 2 <= a->nterm, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: more than N = %" PetscInt_FMT " pairs A_k, B_k", DLOC(d), a->nterm);
    for (PetscInt i = 0; i < d->nfield; i += 2, got_terms++) {
      PetscCall(FieldReal(d, i, "a cosine coefficient A_k", &a->cosc[got_terms]));
      PetscCall(FieldReal(d, i + 1, "a sine coefficient B_k", &a->sinc[got_terms]));
    }
  }
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*AMPLITUDE, DEFINITION=PERIODIC: more than N = %" PetscInt_FMT " pairs A_k, B_k", DLOC(d), a->nterm);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* DEFINITION=DECAY (one line "A0, A, t0, td": a = A0 + A exp(-(t - t0) / td) from t0) and MODULATED (one line
 * "A0, A, t0, omega1, omega2": a = A0 + A sin(omega1 (t - t0)) sin(omega2 (t - t0)) from t0), A0 before t0. */
static PetscErrorCode AmplitudeOneLine(Deck *d, TslAmplitude *a, const char *def)
{
  const PetscBool decay = (PetscBool)!strcmp(def, "DECAY");
  const PetscInt  nval  = decay ? 4 : 5;
  const char     *form  = decay ? "A0, A, t0, td" : "A0, A, t0, omega1, omega2";
  PetscBool       got;

  PetscFunctionBeginUser;
  a->form = decay ? TSL_AMP_DECAY : TSL_AMP_MODULATED;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*AMPLITUDE %s, DEFINITION=%s: expected a line \"%s\"", KLOC(d), a->name, def, form);
  USER_CHECK(d->nfield == nval, LOC_FMT "*AMPLITUDE, DEFINITION=%s: the line holds %s (got %" PetscInt_FMT " values)", DLOC(d), def, form, d->nfield);
  PetscCall(FieldReal(d, 0, "the constant A0", &a->a0));
  PetscCall(FieldReal(d, 1, "the coefficient A", &a->A));
  PetscCall(FieldReal(d, 2, "the starting time t0", &a->t0));
  if (decay) {
    PetscCall(FieldReal(d, 3, "the decay time td", &a->td));
    USER_CHECK(a->td > 0, LOC_FMT "*AMPLITUDE, DEFINITION=DECAY: the decay time td must be > 0 (got %g)", DLOC(d), (double)a->td);
  } else {
    PetscCall(FieldReal(d, 3, "the circular frequency omega1", &a->omega));
    PetscCall(FieldReal(d, 4, "the circular frequency omega2", &a->omega2));
    USER_CHECK(a->omega >= 0 && a->omega2 >= 0, LOC_FMT "*AMPLITUDE, DEFINITION=MODULATED: omega1 and omega2 must not be negative", DLOC(d));
  }
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*AMPLITUDE, DEFINITION=%s takes one data line", DLOC(d), def);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* DEFINITION=EQUALLY SPACED, FIXED INTERVAL=dt[, BEGIN=t_b]: the values a_k (any number per line) at t_b + k dt,
 * interpolated linearly as TABULAR's points. */
static PetscErrorCode AmplitudeEquallySpaced(Deck *d, TslAmplitude *a)
{
  PetscReal dt = 0, begin = 0;
  PetscBool has_dt, got;

  PetscFunctionBeginUser;
  PetscCall(ParamReal(d, "FIXED INTERVAL", &dt, &has_dt));
  PetscCall(ParamReal(d, "BEGIN", &begin, NULL));
  USER_CHECK(has_dt, LOC_FMT "*AMPLITUDE %s, DEFINITION=EQUALLY SPACED needs FIXED INTERVAL= (the time between values)", KLOC(d), a->name);
  USER_CHECK(dt > 0, LOC_FMT "*AMPLITUDE, FIXED INTERVAL must be > 0 (got %g)", KLOC(d), (double)dt);
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    for (PetscInt i = 0; i < d->nfield; i++) {
      PetscCall(TslDeckGrow(&a->t, sizeof(PetscReal), a->n));
      PetscCall(TslDeckGrow(&a->a, sizeof(PetscReal), a->n));
      PetscCall(FieldReal(d, i, "an amplitude value", &a->a[a->n]));
      a->t[a->n] = begin + a->n * dt;
      a->n++;
    }
  }
  USER_CHECK(a->n > 0, LOC_FMT "*AMPLITUDE %s has no data", KLOC(d), a->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwAmplitude(Deck *d, const DeckKeyword *kw)
{
  TslModel     *m = d->m;
  const char   *name, *time, *def;
  char          b1[32], b2[32];
  TslAmplitude *a;
  PetscBool     got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(ParamRequired(d, "NAME", &name));
  USER_CHECK(TslModelFindAmplitude(m, name) < 0, LOC_FMT "amplitude %s is defined twice", KLOC(d), name);
  time = ParamUpper(d, "TIME", b1, sizeof(b1));
  def  = ParamUpper(d, "DEFINITION", b2, sizeof(b2));
  USER_CHECK(!time || !strcmp(time, "STEP TIME") || !strcmp(time, "TOTAL TIME"),
             LOC_FMT "*AMPLITUDE, TIME=%s is not supported (STEP TIME or TOTAL TIME)", KLOC(d), time);
  USER_CHECK(!def || !strcmp(def, "TABULAR") || !strcmp(def, "SMOOTH STEP") || !strcmp(def, "PERIODIC") || !strcmp(def, "EQUALLY SPACED") ||
               !strcmp(def, "DECAY") || !strcmp(def, "MODULATED"),
             LOC_FMT "*AMPLITUDE, DEFINITION=%s is not supported (TABULAR, EQUALLY SPACED, SMOOTH STEP, PERIODIC, DECAY or MODULATED)", KLOC(d), def);
  PetscCall(TslDeckGrow(&m->amplitudes, sizeof(TslAmplitude), m->namplitude));
  a = &m->amplitudes[m->namplitude++];
  PetscCall(CopyName(d, d->kwloc, a->name, name));
  a->total_time = (time && !strcmp(time, "TOTAL TIME")) ? PETSC_TRUE : PETSC_FALSE;
  a->smooth     = (def && !strcmp(def, "SMOOTH STEP")) ? PETSC_TRUE : PETSC_FALSE;
  a->loc        = d->kwloc;
  USER_CHECK(!(Param(d, "FIXED INTERVAL") || Param(d, "BEGIN")) || (def && !strcmp(def, "EQUALLY SPACED")),
             LOC_FMT "*AMPLITUDE, FIXED INTERVAL= and BEGIN= belong to DEFINITION=EQUALLY SPACED", KLOC(d));
  if (def && !strcmp(def, "PERIODIC")) {
    PetscCall(AmplitudePeriodic(d, a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (def && (!strcmp(def, "DECAY") || !strcmp(def, "MODULATED"))) {
    PetscCall(AmplitudeOneLine(d, a, def));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (def && !strcmp(def, "EQUALLY SPACED")) {
    PetscCall(AmplitudeEquallySpaced(d, a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield % 2 == 0, LOC_FMT "*AMPLITUDE data lines hold (time, value) pairs; got an odd number of values", DLOC(d));
    for (PetscInt i = 0; i < d->nfield; i += 2) {
      PetscCall(TslDeckGrow(&a->t, sizeof(PetscReal), a->n));
      PetscCall(TslDeckGrow(&a->a, sizeof(PetscReal), a->n));
      PetscCall(FieldReal(d, i, "a time", &a->t[a->n]));
      PetscCall(FieldReal(d, i + 1, "an amplitude value", &a->a[a->n]));
      USER_CHECK(a->n == 0 || a->t[a->n] >= a->t[a->n - 1], LOC_FMT "amplitude times must not decrease (%g after %g)", DLOC(d), (double)a->t[a->n],
                 (double)a->t[a->n - 1]);
      a->n++;
    }
  }
  USER_CHECK(a->n > 0, LOC_FMT "*AMPLITUDE %s has no data", KLOC(d), name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwPhysical(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(ParamReal(d, "ABSOLUTE ZERO", &d->m->absolute_zero, &d->m->has_absolute_zero));
  PetscCall(ParamReal(d, "STEFAN BOLTZMANN", &d->m->stefan_boltzmann, &d->m->has_stefan_boltzmann));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A dof the model's elements carry (the element rows say which; before any element, any of the
 * dialect's 1..6 and 11). */
static PetscBool ValidDof(const Deck *d, PetscInt dof)
{
  if (d->m->nelem > 0) return TslElementTypeHasDof(TslElementTypeGet(d->m->elem_type[0]), dof);
  return ((dof >= 1 && dof <= 6) || dof == 11) ? PETSC_TRUE : PETSC_FALSE;
}

static const char *ValidDofList(const Deck *d, char *buf, size_t len)
{
  if (d->m->nelem > 0) return TslElementTypeDofList(TslElementTypeGet(d->m->elem_type[0]), buf, len);
  return "1..6, 11";
}

static PetscErrorCode KwEquation(Deck *d, const DeckKeyword *kw)
{
  TslModel *m = d->m;
  PetscBool got;

  PetscFunctionBeginUser;
  (void)kw;
  for (;;) {
    TslEquation *e;
    PetscInt     n;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield == 1, LOC_FMT "*EQUATION: expected the number of terms alone on this line", DLOC(d));
    PetscCall(FieldInt(d, 0, "the number of terms", &n));
    USER_CHECK(n >= 1, LOC_FMT "*EQUATION needs at least one term", DLOC(d));
    PetscCall(TslDeckGrow(&m->equations, sizeof(TslEquation), m->nequation));
    e      = &m->equations[m->nequation++];
    e->loc = d->loc;
    /* the terms are stored as they are read (e->n counts them), not allocated from n: n is the deck's
     * word, and a mutated 1000000000 must give the message below, not an allocation failure */
    while (e->n < n) {
      PetscCall(DataLine(d, 0, &got));
      USER_CHECK(got, LOC_FMT "*EQUATION with %" PetscInt_FMT " terms has only %" PetscInt_FMT, TSL_LOC_ARGS(m, e->loc), n, e->n);
      USER_CHECK(d->nfield % 3 == 0 && e->n + d->nfield / 3 <= n,
                 LOC_FMT "*EQUATION terms are (node, dof, coefficient) triples, %" PetscInt_FMT " in all", DLOC(d), n);
      for (PetscInt i = 0; i < d->nfield; i += 3) {
        PetscInt  k = e->n, label_id;
        PetscBool label;
        PetscCall(InstanceLabel(d, d->field[i], PETSC_TRUE, &label_id, &label));
        USER_CHECK(label || IsInteger(d->field[i]), LOC_FMT "*EQUATION with a node set (%s) is not supported yet; give node ids", DLOC(d),
                   d->field[i]);
        PetscCall(TslDeckGrow(&e->node, sizeof(PetscInt), k));
        PetscCall(TslDeckGrow(&e->dof, sizeof(PetscInt), k));
        PetscCall(TslDeckGrow(&e->coef, sizeof(PetscReal), k));
        e->n++;
        if (label)
          e->node[k] = label_id;
        else
          PetscCall(FieldId(d, i, "a node id", &e->node[k]));
        PetscCall(FieldInt(d, i + 1, "a degree of freedom", &e->dof[k]));
        USER_CHECK(ValidDof(d, e->dof[k]), LOC_FMT "bad degree of freedom %" PetscInt_FMT " (valid: 1..%" PetscInt_FMT ", 11)", DLOC(d), e->dof[k],
                   m->dim ? m->dim : 3);
        PetscCall(FieldReal(d, i + 2, "a coefficient", &e->coef[k]));
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- contact --------------------------------------------------------------------------------
 * *SURFACE INTERACTION opens a block, like *MATERIAL: the interface-law keywords that follow it
 * (block IN_INTERACTION) fill it until any other keyword. Values are range-checked in TslModelCheck. */

static PetscErrorCode KwSurfaceInteraction(Deck *d, const DeckKeyword *kw)
{
  TslModel       *m = d->m;
  TslInteraction *it;
  const char     *name;
  PetscBool       got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(ParamRequired(d, "NAME", &name));
  USER_CHECK(TslModelFindInteraction(m, name) < 0, LOC_FMT "surface interaction %s is defined twice", KLOC(d), name);
  PetscCall(TslDeckGrow(&m->interactions, sizeof(TslInteraction), m->ninteraction));
  it = &m->interactions[m->ninteraction];
  PetscCall(CopyName(d, d->kwloc, it->name, name));
  it->loc                              = d->kwloc;
  it->thickness                        = 1.0;
  it->behavior.enforcement             = TSL_CONTACT_HARD_PENALTY;
  it->friction.slip_tolerance          = 0.005;
  it->heat_generation.fraction         = 1.0;
  it->heat_generation.weight_secondary = 0.5;
  d->interaction                       = m->ninteraction++;
  PetscCall(DataLine(d, 0, &got)); /* Abaqus: optional out-of-plane thickness (2D) */
  if (got) {
    USER_CHECK(d->nfield <= 1, LOC_FMT "*SURFACE INTERACTION data line needs only the out-of-plane thickness", DLOC(d));
    PetscCall(FieldRealDefault(d, 0, "the out-of-plane thickness", 1.0, &it->thickness));
    USER_CHECK(it->thickness > 0, LOC_FMT "the out-of-plane thickness must be positive", DLOC(d));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Marks a law of the open interaction as given here, after checking that it was not given before. */
static PetscErrorCode InteractionLaw(Deck *d, PetscBool *given, TslLoc *loc)
{
  PetscFunctionBeginUser;
  USER_CHECK(!*given, LOC_FMT "*%s is given twice for surface interaction %s (first at %s:%" PetscInt_FMT ")", KLOC(d), d->kw,
             d->m->interactions[d->interaction].name, TslDeckFileName(d->m, loc->file), loc->line);
  *given = PETSC_TRUE;
  *loc   = d->kwloc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Fails when the keyword has another data line: the laws below take one row (no dependencies). */
static PetscErrorCode NoMoreRows(Deck *d, const char *kwname, const char *what)
{
  PetscBool got;

  PetscFunctionBeginUser;
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*%s takes one data line (%s is not supported yet)", DLOC(d), kwname, what);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Field i must be absent or blank: a feature of the dialect not supported yet. */
static PetscErrorCode FieldUnsupported(Deck *d, PetscInt i, const char *kwname, const char *what)
{
  PetscFunctionBeginUser;
  USER_CHECK(i >= d->nfield || !d->field[i][0], LOC_FMT "*%s: %s is not supported yet", DLOC(d), kwname, what);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwSurfaceBehavior(Deck *d, const DeckKeyword *kw)
{
  TslSurfaceBehavior *b = &d->m->interactions[d->interaction].behavior;
  char                buf[32];
  const char         *po      = ParamUpper(d, "PRESSURE-OVERCLOSURE", buf, sizeof(buf));
  PetscBool           penalty = Param(d, "PENALTY") ? PETSC_TRUE : PETSC_FALSE, got;
  PetscBool           auglag  = Param(d, "AUGMENTED LAGRANGE") ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(InteractionLaw(d, &b->given, &b->loc));
  USER_CHECK(!po || !strcmp(po, "HARD") || !strcmp(po, "LINEAR") || !strcmp(po, "TIED"),
             LOC_FMT "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=%s is not supported yet (HARD, LINEAR or TIED)", KLOC(d), po);
  if (po && !strcmp(po, "TIED")) {
    /* the dialect's tied penalty contact (slope K, with a stick slope on *FRICTION) is enforced exactly here: the
     * interaction's pairs become ties (TslTie), so the slope line is read and not used */
    USER_CHECK(!penalty && !auglag, LOC_FMT "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED takes neither PENALTY nor AUGMENTED LAGRANGE", KLOC(d));
    b->tied = PETSC_TRUE;
    PetscCall(DataLine(d, 0, &got));
    if (got) {
      USER_CHECK(d->nfield == 1, LOC_FMT "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED data line: the slope of the pressure-overclosure relation", DLOC(d));
      PetscCall(FieldReal(d, 0, "the slope of the pressure-overclosure relation", &b->penalty_stiffness));
      USER_CHECK(b->penalty_stiffness > 0, LOC_FMT "the slope of the pressure-overclosure relation must be positive", DLOC(d));
      PetscCall(NoMoreRows(d, "SURFACE BEHAVIOR", "a second data line"));
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  USER_CHECK(!(penalty && auglag), LOC_FMT "*SURFACE BEHAVIOR: PENALTY and AUGMENTED LAGRANGE exclude each other", KLOC(d));
  USER_CHECK(!Param(d, "DIRECT"), LOC_FMT "*SURFACE BEHAVIOR, DIRECT is not supported (use PENALTY or AUGMENTED LAGRANGE)", KLOC(d));
  USER_CHECK(!Param(d, "NO SEPARATION"), LOC_FMT "*SURFACE BEHAVIOR, NO SEPARATION is not supported yet", KLOC(d));
  b->enforcement = auglag ? TSL_CONTACT_AUGMENTED_LAGRANGE : TSL_CONTACT_HARD_PENALTY;
  if (po && !strcmp(po, "LINEAR")) {
    /* p = K x overclosure, zero when open: the penalty law with the user's slope as its stiffness. The dialect's
     * further fields are CalculiX's tension at large clearances (a small regularisation: an open gap carries no
     * pressure here) and its face-to-face c0; read and ignored, with a warning. */
    USER_CHECK(!penalty && !auglag,
               LOC_FMT "*SURFACE BEHAVIOR: PENALTY and AUGMENTED LAGRANGE apply to HARD contact, not to PRESSURE-OVERCLOSURE=LINEAR", KLOC(d));
    PetscCall(DataLine(d, 0, &got));
    USER_CHECK(got, LOC_FMT "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR needs a data line: the slope of the pressure-overclosure relation",
               KLOC(d));
    USER_CHECK(d->nfield <= 3, LOC_FMT "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR data line: slope[, tension at large clearances, c0]", DLOC(d));
    PetscCall(FieldReal(d, 0, "the slope of the pressure-overclosure relation", &b->penalty_stiffness));
    USER_CHECK(b->penalty_stiffness > 0, LOC_FMT "the slope of the pressure-overclosure relation must be positive", DLOC(d));
    for (PetscInt i = 1; i < d->nfield; i++) {
      PetscReal v;
      if (!d->field[i][0]) continue;
      PetscCall(FieldReal(d, i, i == 1 ? "the tension at large clearances" : "c0", &v));
      if (v != 0)
        PetscCall(PetscPrintf(PETSC_COMM_SELF,
                              LOC_FMT "warning: *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR: field %" PetscInt_FMT " (%s) is ignored\n", DLOC(d),
                              i + 1, i == 1 ? "CalculiX's tension at large clearances: an open gap carries no pressure" : "CalculiX's c0"));
    }
    PetscCall(NoMoreRows(d, "SURFACE BEHAVIOR", "a second data line"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DataLine(d, 0, &got)); /* optional: penalty stiffness, clearance at zero pressure, stiffness scale */
  if (!got) PetscFunctionReturn(PETSC_SUCCESS);
  USER_CHECK(d->nfield <= 3, LOC_FMT "*SURFACE BEHAVIOR data line: penalty stiffness[, clearance, scale factor]", DLOC(d));
  PetscCall(FieldRealDefault(d, 0, "the penalty stiffness", 0.0, &b->penalty_stiffness));
  USER_CHECK(b->penalty_stiffness >= 0, LOC_FMT "the penalty stiffness must be positive (or blank for the default)", DLOC(d));
  PetscCall(FieldUnsupported(d, 1, "SURFACE BEHAVIOR", "a clearance at zero contact pressure"));
  PetscCall(FieldUnsupported(d, 2, "SURFACE BEHAVIOR", "a penalty stiffness scale factor"));
  PetscCall(NoMoreRows(d, "SURFACE BEHAVIOR", "a pressure-overclosure table"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwFriction(Deck *d, const DeckKeyword *kw)
{
  TslFriction *f = &d->m->interactions[d->interaction].friction;
  PetscBool    got, tol;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(InteractionLaw(d, &f->given, &f->loc));
  f->lagrange = Param(d, "LAGRANGE") ? PETSC_TRUE : PETSC_FALSE;
  f->rough    = Param(d, "ROUGH") ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(ParamReal(d, "SLIP TOLERANCE", &f->slip_tolerance, &tol));
  USER_CHECK(!(tol && f->lagrange), LOC_FMT "*FRICTION: SLIP TOLERANCE does not apply with LAGRANGE", KLOC(d));
  USER_CHECK(f->slip_tolerance > 0, LOC_FMT "*FRICTION: SLIP TOLERANCE must be positive", KLOC(d));
  {
    PetscBool es;
    PetscCall(ParamReal(d, "ELASTIC SLIP", &f->elastic_slip, &es));
    USER_CHECK(!es || (f->elastic_slip > 0 && !f->lagrange && !tol),
               LOC_FMT "*FRICTION: ELASTIC SLIP must be positive, and excludes LAGRANGE and SLIP TOLERANCE", KLOC(d));
  }
  PetscCall(DataLine(d, 0, &got));
  if (!got) {
    USER_CHECK(f->rough, LOC_FMT "*FRICTION needs a data line with the friction coefficient", KLOC(d));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* CalculiX: mu, stick slope. Abaqus: mu, then slip rate, pressure, temperature... for dependent data. */
  USER_CHECK(d->nfield >= 1 && d->nfield <= 2, LOC_FMT "*FRICTION data line: friction coefficient[, stick slope]", DLOC(d));
  PetscCall(FieldReal(d, 0, "the friction coefficient", &f->mu));
  PetscCall(FieldRealDefault(d, 1, "the stick slope", 0.0, &f->stick_slope));
  USER_CHECK(f->stick_slope >= 0, LOC_FMT "the stick slope must be positive (or blank for the default)", DLOC(d));
  PetscCall(NoMoreRows(d, "FRICTION", "rate-, pressure- or temperature-dependent friction"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sorts the rows of a two-column table by x (the deck may list them in any order). */
static PetscErrorCode SortTable(PetscInt n, PetscReal x[], PetscReal y[])
{
  PetscInt  *perm;
  PetscReal *tx, *ty;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(n, &perm, n, &tx, n, &ty));
  for (PetscInt i = 0; i < n; i++) perm[i] = i, tx[i] = x[i], ty[i] = y[i];
  PetscCall(PetscSortRealWithPermutation(n, tx, perm));
  for (PetscInt i = 0; i < n; i++) x[i] = tx[perm[i]], y[i] = ty[perm[i]];
  PetscCall(PetscFree3(perm, tx, ty));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwGapConductance(Deck *d, const DeckKeyword *kw)
{
  TslGapConductance *g     = &d->m->interactions[d->interaction].conductance;
  PetscInt           deps  = 0;
  PetscReal          theta = 0;
  PetscBool          got, has_theta = PETSC_FALSE;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(InteractionLaw(d, &g->given, &g->loc));
  USER_CHECK(!Param(d, "USER"), LOC_FMT "*GAP CONDUCTANCE, USER (subroutine GAPCON) is not supported", KLOC(d));
  PetscCall(ParamInt(d, "DEPENDENCIES", &deps));
  USER_CHECK(deps == 0, LOC_FMT "*GAP CONDUCTANCE, DEPENDENCIES (field variables) is not supported yet", KLOC(d));
  g->by_pressure = Param(d, "PRESSURE") ? PETSC_TRUE : PETSC_FALSE;
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield >= 1 && d->nfield <= 3,
               LOC_FMT "*GAP CONDUCTANCE data line: conductance, %s[, temperature] (mass flow rate and field variables "
                       "are not supported)",
               DLOC(d), g->by_pressure ? "pressure" : "clearance");
    PetscCall(TslDeckGrow(&g->value, sizeof(PetscReal), g->n));
    PetscCall(TslDeckGrow(&g->abscissa, sizeof(PetscReal), g->n));
    PetscCall(FieldReal(d, 0, "the gap conductance", &g->value[g->n]));
    PetscCall(FieldRealDefault(d, 1, g->by_pressure ? "the contact pressure" : "the clearance", 0.0, &g->abscissa[g->n]));
    g->n++;
    if (d->nfield > 2 && d->field[2][0]) { /* one temperature for the whole table is no dependence */
      PetscReal t;
      PetscCall(FieldReal(d, 2, "the temperature", &t));
      USER_CHECK(!has_theta || t == theta, LOC_FMT "temperature-dependent *GAP CONDUCTANCE (temperature %g after %g) is not supported yet", DLOC(d),
                 (double)t, (double)theta);
      theta = t, has_theta = PETSC_TRUE;
    }
  }
  USER_CHECK(g->n > 0, LOC_FMT "*GAP CONDUCTANCE needs at least one data line", KLOC(d));
  if (!g->by_pressure && g->n > 1)
    /* the dialects part here: Abaqus reads the second column as clearance unless PRESSURE is given, CalculiX
     * always as contact pressure. This code follows Abaqus; a CalculiX deck would silently change meaning. */
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          LOC_FMT "warning: *GAP CONDUCTANCE without PRESSURE: the second column is read as the clearance (Abaqus); CalculiX "
                                  "reads it as the contact pressure, which needs the PRESSURE parameter here\n",
                          KLOC(d)));
  PetscCall(SortTable(g->n, g->abscissa, g->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwGapRadiation(Deck *d, const DeckKeyword *kw)
{
  TslGapRadiation *r = &d->m->interactions[d->interaction].radiation;
  PetscBool        got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(InteractionLaw(d, &r->given, &r->loc));
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*GAP RADIATION needs a data line with the two emissivities", KLOC(d));
  USER_CHECK(d->nfield == 2, LOC_FMT "*GAP RADIATION first data line: emissivity of the main surface, of the secondary", DLOC(d));
  PetscCall(FieldReal(d, 0, "the emissivity of the main surface", &r->emissivity_main));
  PetscCall(FieldReal(d, 1, "the emissivity of the secondary surface", &r->emissivity_secondary));
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield >= 1 && d->nfield <= 2, LOC_FMT "*GAP RADIATION data line: effective view factor, clearance", DLOC(d));
    PetscCall(TslDeckGrow(&r->view_factor, sizeof(PetscReal), r->n));
    PetscCall(TslDeckGrow(&r->clearance, sizeof(PetscReal), r->n));
    PetscCall(FieldReal(d, 0, "the effective view factor", &r->view_factor[r->n]));
    PetscCall(FieldRealDefault(d, 1, "the clearance", 0.0, &r->clearance[r->n]));
    r->n++;
  }
  USER_CHECK(r->n > 0, LOC_FMT "*GAP RADIATION needs the view factor vs clearance lines after the emissivities", KLOC(d));
  PetscCall(SortTable(r->n, r->clearance, r->view_factor));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwGapHeatGeneration(Deck *d, const DeckKeyword *kw)
{
  TslGapHeatGeneration *h = &d->m->interactions[d->interaction].heat_generation;
  PetscReal             slip_rate;
  PetscBool             got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(InteractionLaw(d, &h->given, &h->loc));
  USER_CHECK(!Param(d, "USER"), LOC_FMT "*GAP HEAT GENERATION, USER is not supported", KLOC(d));
  PetscCall(DataLine(d, 0, &got));
  if (!got) PetscFunctionReturn(PETSC_SUCCESS);
  USER_CHECK(d->nfield <= 3,
             LOC_FMT "*GAP HEAT GENERATION data line: fraction converted to heat, weight of the "
                     "secondary surface",
             DLOC(d));
  PetscCall(FieldRealDefault(d, 0, "the fraction converted to heat", 1.0, &h->fraction));
  PetscCall(FieldRealDefault(d, 1, "the weight of the secondary surface", 0.5, &h->weight_secondary));
  /* CalculiX third value: a prescribed slip rate; negative means "computed", which is what we do */
  PetscCall(FieldRealDefault(d, 2, "the slip rate", -1.0, &slip_rate));
  USER_CHECK(slip_rate < 0, LOC_FMT "*GAP HEAT GENERATION: a prescribed slip rate (third value) is not supported yet", DLOC(d));
  PetscCall(NoMoreRows(d, "GAP HEAT GENERATION", "more than one row"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The data lines of a *TIE (one: the dialect ties one secondary surface to one main surface) or of a tied
 * *CONTACT PAIR (one or more): secondary surface, main surface. */
static PetscErrorCode TieLines(Deck *d, PetscBool pair, PetscReal tolerance, PetscBool adjust)
{
  TslModel  *m     = d->m;
  PetscInt   first = m->ntie;
  PetscBool  got;
  const char *kwname = pair ? "*CONTACT PAIR, TIED" : "*TIE", *name = Param(d, "NAME");

  PetscFunctionBeginUser;
  for (;;) {
    TslTie *t;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(pair || m->ntie == first, LOC_FMT "*TIE takes one data line (secondary surface, main surface); give a second *TIE for another", DLOC(d));
    USER_CHECK(d->nfield == 2 && d->field[0][0] && d->field[1][0], LOC_FMT "%s data line needs: secondary surface, main surface", DLOC(d), kwname);
    PetscCall(TslDeckGrow(&m->ties, sizeof(TslTie), m->ntie));
    t = &m->ties[m->ntie++];
    PetscCall(PetscMemzero(t, sizeof(*t)));
    t->loc       = pair ? d->loc : d->kwloc; /* a pair's errors name its data line (as contact's do), a *TIE's its keyword */
    t->tolerance = tolerance;
    t->adjust    = adjust;
    t->from_pair = pair;
    if (name) PetscCall(CopyName(d, d->kwloc, t->name, name));
    PetscCall(CopyName(d, d->loc, t->secondary, d->field[0]));
    PetscCall(CopyName(d, d->loc, t->main, d->field[1]));
  }
  USER_CHECK(m->ntie > first, LOC_FMT "%s needs a data line: secondary surface, main surface", KLOC(d), kwname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *TIE: POSITION TOLERANCE (the dialect's default when absent or below 1e-10: 2.5 % of a typical element size),
 * ADJUST=YES|NO (Abaqus's parameter, default YES), NAME; CalculiX's CYCLIC SYMMETRY, MULTISTAGE and the fluid ties
 * are other constraints, refused. */
static PetscErrorCode KwTie(Deck *d, const DeckKeyword *kw)
{
  PetscReal   tol = 0;
  char        abuf[16];
  const char *adjust = ParamUpper(d, "ADJUST", abuf, sizeof(abuf));
  const char *other[] = {"CYCLIC SYMMETRY", "MULTISTAGE", "FLUID PERIODIC", "FLUID CYCLIC"};

  PetscFunctionBeginUser;
  (void)kw;
  for (size_t i = 0; i < sizeof(other) / sizeof(other[0]); i++)
    USER_CHECK(!Param(d, other[i]), LOC_FMT "*TIE, %s is not supported (only the tie of adjacent surfaces)", KLOC(d), other[i]);
  USER_CHECK(!adjust || !strcmp(adjust, "YES") || !strcmp(adjust, "NO"), LOC_FMT "*TIE: ADJUST=%s (YES or NO)", KLOC(d), adjust);
  PetscCall(ParamReal(d, "POSITION TOLERANCE", &tol, NULL));
  USER_CHECK(tol >= 0, LOC_FMT "*TIE: POSITION TOLERANCE must not be negative", KLOC(d));
  if (tol < 1e-10) tol = 0; /* the dialect: the default below 1e-10 */
  PetscCall(TieLines(d, PETSC_FALSE, tol, (PetscBool)(!adjust || !strcmp(adjust, "YES"))));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwContactPair(Deck *d, const DeckKeyword *kw)
{
  TslModel      *m = d->m;
  TslContactPair proto;
  const char    *inter, *type, *adjust = Param(d, "ADJUST");
  char           tbuf[32];
  PetscInt       first = m->npair;
  PetscBool      got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(PetscMemzero(&proto, sizeof(proto)));
  PetscCall(ParamRequired(d, "INTERACTION", &inter));
  PetscCall(CopyName(d, d->kwloc, proto.interaction, inter));
  proto.interaction_index = -1;
  type                    = ParamUpper(d, "TYPE", tbuf, sizeof(tbuf));
  USER_CHECK(!type || !strcmp(type, "NODE TO SURFACE") || !strcmp(type, "SURFACE TO SURFACE"),
             LOC_FMT "*CONTACT PAIR, TYPE=%s is not supported (NODE TO SURFACE or SURFACE TO SURFACE)", KLOC(d), type);
  proto.type = (type && !strcmp(type, "SURFACE TO SURFACE")) ? TSL_CONTACT_SURFACE_TO_SURFACE : TSL_CONTACT_NODE_TO_SURFACE;
  if (Param(d, "TIED")) {
    /* a tied pair is a tie of its surfaces (TslTie): its interaction's laws do not apply (the interface is
     * perfectly conducting and carries any traction), its ADJUST is the tie's */
    PetscCall(TieLines(d, PETSC_TRUE, 0, (PetscBool)(adjust && adjust[0] && (!(isdigit((unsigned char)adjust[0]) || adjust[0] == '.') || strtod(adjust, NULL) > 0))));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  proto.small_sliding = Param(d, "SMALL SLIDING") ? PETSC_TRUE : PETSC_FALSE;
  {
    /* explicit steps' enforcement (docs/explicit.md): PENALTY unless KINEMATIC is asked for */
    char        mbuf[32];
    const char *mc = ParamUpper(d, "MECHANICAL CONSTRAINT", mbuf, sizeof(mbuf));
    USER_CHECK(!mc || !strcmp(mc, "PENALTY") || !strcmp(mc, "KINEMATIC"),
               LOC_FMT "*CONTACT PAIR, MECHANICAL CONSTRAINT=%s is not supported (PENALTY or KINEMATIC)", KLOC(d), mc);
    proto.kinematic = (PetscBool)(mc && !strcmp(mc, "KINEMATIC"));
  }
  proto.smooth        = 0.2;
  PetscCall(ParamReal(d, "SMOOTH", &proto.smooth, NULL));
  /* the contact kinematics smooth a fraction s < 1/2 of each segment at either end (s = 1/2 would leave no straight part) */
  USER_CHECK(proto.smooth >= 0 && proto.smooth < 0.5, LOC_FMT "*CONTACT PAIR: SMOOTH must lie in [0, 0.5) (got %g)", KLOC(d), (double)proto.smooth);
  if (adjust) {
    USER_CHECK(adjust[0], LOC_FMT "*CONTACT PAIR: ADJUST= needs a distance or a node set", KLOC(d));
    proto.adjust_given = PETSC_TRUE;
    if (isdigit((unsigned char)adjust[0]) || adjust[0] == '.' || adjust[0] == '+' || adjust[0] == '-') {
      PetscCall(ParamReal(d, "ADJUST", &proto.adjust, NULL));
      USER_CHECK(proto.adjust >= 0, LOC_FMT "*CONTACT PAIR: ADJUST must not be negative", KLOC(d));
    } else
      PetscCall(CopyName(d, d->kwloc, proto.adjust_set, adjust));
  }
  for (;;) {
    TslContactPair *p;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(d->nfield == 2 && d->field[0][0] && d->field[1][0], LOC_FMT "*CONTACT PAIR data line needs: secondary surface, main surface", DLOC(d));
    PetscCall(TslDeckGrow(&m->pairs, sizeof(TslContactPair), m->npair));
    p      = &m->pairs[m->npair++];
    *p     = proto;
    p->loc = d->loc;
    PetscCall(CopyName(d, d->loc, p->secondary, d->field[0]));
    PetscCall(CopyName(d, d->loc, p->main, d->field[1]));
  }
  USER_CHECK(m->npair > first, LOC_FMT "*CONTACT PAIR needs a data line: secondary surface, main surface", KLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- steps ----------------------------------------------------------------------------------- */

static PetscErrorCode KwStep(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m = d->m;
  TslStep    *s;
  const char *name = Param(d, "NAME"), *nl, *title;
  char        buf[32];
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(TslDeckGrow(&m->steps, sizeof(TslStep), m->nstep));
  s = &m->steps[m->nstep];
  if (name && name[0])
    PetscCall(CopyName(d, d->kwloc, s->name, name));
  else
    PetscCall(PetscSNPrintf(s->name, sizeof(s->name), "Step-%" PetscInt_FMT, m->nstep + 1));
  s->loc     = d->kwloc;
  s->max_inc = 100;
  PetscCall(ParamInt(d, "INC", &s->max_inc));
  USER_CHECK(s->max_inc > 0, LOC_FMT "INC= must be positive", KLOC(d));
  nl = ParamUpper(d, "NLGEOM", buf, sizeof(buf));
  USER_CHECK(!nl || !nl[0] || !strcmp(nl, "YES") || !strcmp(nl, "NO"), LOC_FMT "NLGEOM=%s: expected YES or NO", KLOC(d), nl);
  s->nlgeom       = (nl && strcmp(nl, "NO")) ? PETSC_TRUE : PETSC_FALSE; /* NLGEOM alone means YES in the dialect */
  s->nlgeom_given = nl ? PETSC_TRUE : PETSC_FALSE;                           /* a later step inherits it (check.c, CheckNlgeom) */
  /* EXTRAPOLATION=LINEAR (the dialect's default: each increment starts from the last one's change, scaled),
   * NO; PARABOLIC is taken as LINEAR, with a warning */
  nl = ParamUpper(d, "EXTRAPOLATION", buf, sizeof(buf));
  USER_CHECK(!nl || !strcmp(nl, "LINEAR") || !strcmp(nl, "NO") || !strcmp(nl, "PARABOLIC"),
             LOC_FMT "*STEP, EXTRAPOLATION=%s: expected LINEAR, PARABOLIC or NO", KLOC(d), nl);
  s->no_extrapolation = (PetscBool)(nl && !strcmp(nl, "NO"));
  if (nl && !strcmp(nl, "PARABOLIC"))
    PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "warning: *STEP, EXTRAPOLATION=PARABOLIC is taken as LINEAR (the start of each increment)\n", KLOC(d)));
  nl = ParamUpper(d, "AMPLITUDE", buf, sizeof(buf));
  if (nl) {
    USER_CHECK(!strcmp(nl, "RAMP") || !strcmp(nl, "STEP"), LOC_FMT "*STEP, AMPLITUDE=%s: expected RAMP or STEP", KLOC(d), nl);
    s->amp_given   = PETSC_TRUE;
    s->amp_default = !strcmp(nl, "RAMP") ? TSL_AMP_RAMP : TSL_AMP_STEP;
  }
  s->dt0 = s->period = s->dtmax = 1.0;
  s->dtmin                      = 1e-5;
  s->out_number_interval        = d->out_number_model;
  s->out_time_interval          = d->out_time_model;
  s->restart_frequency          = d->restart_frequency;
  s->restart_interval           = d->restart_interval;
  s->restart_overlay            = d->restart_overlay;
  s->restart_loc                = d->restart_loc;
  d->step                       = m->nstep++;
  d->out_frequency              = d->out_frequency_model;
  /* Abaqus allows one data line here, the step's title (free text, commas included): read and not kept (the
   * model has no place for it); a second data line is an error (DeckParse) */
  PetscCall(RawNext(d, &title, &got));
  if (got && IsKeywordLine(title)) RawUnget(d);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwEndStep(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  d->step = -1;
  if (d->restart_stop && d->m->nstep == d->restart_stop && d->depth >= d->restart_depth) {
    /* *RESTART, READ: the old job's deck ends here for this job; the restart deck's own steps follow */
    for (PetscInt k = d->restart_depth - 1; k < d->depth; k++) d->frame[k].pos = d->frame[k].len;
    d->restart_stop = 0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The implicit procedures' data line: initial increment, step period, minimum and maximum increment (what names
 * the keyword in the message). */
/* The data line just read: initial increment, step period, minimum, maximum increment. */
static PetscErrorCode StepIncrementFields(Deck *d, TslStep *s, const char *what)
{
  PetscFunctionBeginUser;
  USER_CHECK(d->nfield <= 4, LOC_FMT "%s data line: initial increment, step period, minimum, maximum increment", DLOC(d), what);
  PetscCall(FieldRealDefault(d, 0, "the initial increment", 1.0, &s->dt0));
  PetscCall(FieldRealDefault(d, 1, "the step period", 1.0, &s->period));
  USER_CHECK(s->dt0 > 0 && s->period > 0, LOC_FMT "the initial increment and the step period must be positive", DLOC(d));
  PetscCall(FieldRealDefaultZero(d, 2, "the minimum increment", PetscMin(s->dt0, 1e-5 * s->period), &s->dtmin));
  PetscCall(FieldRealDefaultZero(d, 3, "the maximum increment", s->period, &s->dtmax));
  USER_CHECK(s->dtmin > 0 && s->dtmin <= s->dtmax, LOC_FMT "need 0 < minimum increment <= maximum increment", DLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode StepIncrements(Deck *d, TslStep *s, const char *what)
{
  PetscBool got;

  PetscFunctionBeginUser;
  PetscCall(DataLine(d, 0, &got));
  s->dt0 = s->period = 1.0;
  if (got) {
    PetscCall(StepIncrementFields(d, s, what));
  } else {
    s->dtmin = PetscMin(s->dt0, 1e-5 * s->period);
    s->dtmax = s->period;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
/* *CONTROLS, PARAMETERS=FIELD[, FIELD=GLOBAL | DISPLACEMENT | TEMPERATURE]: one data line
 *   R_n, C_n, q_0, q_u, R_P, eps, C_eps, R_l
 * (blank fields: the dialect's defaults 0.005, 0.01, 0.01, none, 0.02, 1e-5, 1e-3, 1e-8), for both fields (GLOBAL,
 * the default, and CalculiX's only form) or the one named (TslFieldControls). */
static PetscErrorCode FieldControls(Deck *d)
{
  char            buf[32];
  const char     *which  = ParamUpper(d, "FIELD", buf, sizeof(buf));
  const char     *name[8] = {"R_n", "C_n", "q_0", "q_u", "R_P", "eps", "C_eps", "R_l"};
  const PetscReal def[8] = {0.005, 0.01, 0.01, 0, 0.02, 1e-5, 1e-3, 1e-8};
  PetscReal       v[8];
  PetscBool       got;

  PetscFunctionBeginUser;
  USER_CHECK(!which || !strcmp(which, "GLOBAL") || !strcmp(which, "DISPLACEMENT") || !strcmp(which, "TEMPERATURE"),
             LOC_FMT "*CONTROLS, PARAMETERS=FIELD: FIELD=%s is not a field of coupled temperature-displacement steps (GLOBAL, DISPLACEMENT or "
                     "TEMPERATURE)",
             KLOC(d), which);
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*CONTROLS, PARAMETERS=FIELD needs a data line: R_n, C_n, q_0, q_u, R_P, eps, C_eps, R_l", KLOC(d));
  USER_CHECK(d->nfield <= 8, LOC_FMT "*CONTROLS, PARAMETERS=FIELD data line: at most 8 values (R_n, C_n, q_0, q_u, R_P, eps, C_eps, R_l), got %" PetscInt_FMT,
             DLOC(d), d->nfield);
  for (PetscInt i = 0; i < 8; i++) {
    PetscCall(FieldRealDefault(d, i, name[i], def[i], &v[i]));
    if (i == 2 || i == 3) USER_CHECK(v[i] >= 0, LOC_FMT "*CONTROLS, PARAMETERS=FIELD: %s must not be negative (got %g)", DLOC(d), name[i], (double)v[i]);
    else USER_CHECK(v[i] > 0, LOC_FMT "*CONTROLS, PARAMETERS=FIELD: %s must be positive (got %g)", DLOC(d), name[i], (double)v[i]);
  }
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*CONTROLS, PARAMETERS=FIELD takes one data line", DLOC(d));
  for (PetscInt k = 0; k < 2; k++) {
    TslFieldControls *f = &d->m->steps[d->step].field_controls[k];
    if (which && !strcmp(which, k ? "DISPLACEMENT" : "TEMPERATURE")) continue;
    f->given = f->on = PETSC_TRUE, f->loc = d->kwloc;
    f->rn = v[0], f->cn = v[1], f->q0 = v[2], f->qu = v[3], f->rp = v[4], f->eps = v[5], f->ceps = v[6], f->rl = v[7];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *CONTROLS (CalculiX's form): PARAMETERS=TIME INCREMENTATION sets the increment controller from two data lines,
 *   I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A, I_J, I_T
 *   D_f, D_C, D_B, D_A, D_S, D_H, D_D, W_G
 * (blank fields: the dialect's defaults 4, 8, 9, 16, 10, 4, -, 5, -, - and 0.25, 0.5, 0.75, 0.85, -, -, 1.5, -; the
 * second line may be absent); RESET goes back to the defaults, here thermoslide's own controller. What the driver
 * applies (I_C, I_L, I_G, I_A, I_P, D_f, D_B, D_A, D_D) is in docs/keywords.md; the rest is read and checked. FIELD:
 * FieldControls. Other PARAMETERS= (LINE SEARCH, CONTACT, NETWORK, CFD) and Abaqus's forms are read past with a
 * warning. */
static PetscErrorCode KwControls(Deck *d, const DeckKeyword *kw)
{
  TslIncrementControls *c = &d->m->steps[d->step].controls;
  char                  buf[64];
  const char           *par       = ParamUpper(d, "PARAMETERS", buf, sizeof(buf));
  PetscBool             reset     = Param(d, "RESET") ? PETSC_TRUE : PETSC_FALSE, got;
  static const char    *iname[10] = {"I_0", "I_R", "I_P", "I_C", "I_L", "I_G", "I_S", "I_A", "I_J", "I_T"};
  static const char    *dname[8]  = {"D_f", "D_C", "D_B", "D_A", "D_S", "D_H", "D_D", "W_G"};
  const PetscInt        idef[10]  = {4, 8, 9, 16, 10, 4, 0, 5, 0, 0};
  const PetscReal       ddef[8]   = {0.25, 0.5, 0.75, 0.85, 0, 0, 1.5, 0};
  PetscInt              iv[10];
  PetscReal             dv[8];

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!(reset && par), LOC_FMT "*CONTROLS: RESET and PARAMETERS= exclude each other", KLOC(d));
  if (reset) {
    PetscCall(DataLine(d, 0, &got));
    USER_CHECK(!got, LOC_FMT "*CONTROLS, RESET takes no data lines", DLOC(d));
    memset(c, 0, sizeof(*c));
    c->given = c->reset = PETSC_TRUE;
    c->loc              = d->kwloc;
    for (PetscInt k = 0; k < 2; k++) {
      TslFieldControls *f = &d->m->steps[d->step].field_controls[k];
      memset(f, 0, sizeof(*f));
      f->given = PETSC_TRUE, f->loc = d->kwloc;
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (par && !strcmp(par, "FIELD")) {
    PetscCall(FieldControls(d));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!par || strcmp(par, "TIME INCREMENTATION")) {
    char what[96];
    PetscCall(PetscSNPrintf(what, sizeof(what), "*CONTROLS%s%s", par ? ", PARAMETERS=" : "", par ? par : ""));
    PetscCall(ReadPast(d, what, CONTROLS_NOTE));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*CONTROLS, PARAMETERS=TIME INCREMENTATION needs a data line: I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A, I_J, I_T", KLOC(d));
  USER_CHECK(d->nfield <= 10,
             LOC_FMT "*CONTROLS, PARAMETERS=TIME INCREMENTATION first data line: at most 10 integers (I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A, I_J, "
                     "I_T), got %" PetscInt_FMT,
             DLOC(d), d->nfield);
  for (PetscInt i = 0; i < 10; i++) {
    char what[48];
    iv[i] = idef[i];
    if (i >= d->nfield || !d->field[i][0]) continue;
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s (an iteration count)", iname[i]));
    PetscCall(FieldInt(d, i, what, &iv[i]));
    USER_CHECK(iv[i] >= 0, LOC_FMT "*CONTROLS: %s must not be negative (got %" PetscInt_FMT ")", DLOC(d), iname[i], iv[i]);
  }
  USER_CHECK(iv[3] >= 1, LOC_FMT "*CONTROLS: I_C, the most iterations of an increment, must be at least 1", DLOC(d));
  for (PetscInt i = 0; i < 8; i++) dv[i] = ddef[i];
  PetscCall(DataLine(d, 0, &got));
  if (got) {
    USER_CHECK(
        d->nfield <= 8,
        LOC_FMT
        "*CONTROLS, PARAMETERS=TIME INCREMENTATION second data line: at most 8 factors (D_f, D_C, D_B, D_A, D_S, D_H, D_D, W_G), got %" PetscInt_FMT,
        DLOC(d), d->nfield);
    for (PetscInt i = 0; i < 8; i++) {
      char what[48];
      PetscCall(PetscSNPrintf(what, sizeof(what), "%s (a factor)", dname[i]));
      PetscCall(FieldRealDefault(d, i, what, ddef[i], &dv[i]));
    }
    /* the cutback factors shrink the increment, the growth factor enlarges it */
    for (PetscInt i = 0; i < 4; i++)
      USER_CHECK(dv[i] > 0 && dv[i] < 1, LOC_FMT "*CONTROLS: %s must lie in (0, 1) (got %g)", DLOC(d), dname[i], (double)dv[i]);
    USER_CHECK(dv[6] >= 1, LOC_FMT "*CONTROLS: D_D, the growth factor, must be at least 1 (got %g)", DLOC(d), (double)dv[6]);
  }
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*CONTROLS, PARAMETERS=TIME INCREMENTATION takes two data lines at most", DLOC(d));
  c->given = PETSC_TRUE, c->reset = PETSC_FALSE, c->loc = d->kwloc;
  c->i0 = iv[0], c->ir = iv[1], c->ip = iv[2], c->ic = iv[3], c->il = iv[4], c->ig = iv[5], c->is = iv[6], c->ia = iv[7], c->ij = iv[8],
  c->it = iv[9];
  c->df = dv[0], c->dc = dv[1], c->db = dv[2], c->da = dv[3], c->ds = dv[4], c->dh = dv[5], c->dd = dv[6], c->wg = dv[7];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwCoupled(Deck *d, const DeckKeyword *kw)
{
  TslStep  *s = &d->m->steps[d->step];
  PetscBool set;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!s->coupled, LOC_FMT "step %s already has a procedure", KLOC(d), s->name);
  s->coupled = PETSC_TRUE;
  s->steady  = Param(d, "STEADY STATE") ? PETSC_TRUE : PETSC_FALSE;
  s->direct  = Param(d, "DIRECT") ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(ParamReal(d, "DELTMX", &s->deltmx, &set));
  USER_CHECK(!set || s->deltmx >= 0, LOC_FMT "DELTMX must not be negative", KLOC(d));
  if (!s->amp_given) s->amp_default = s->steady ? TSL_AMP_RAMP : TSL_AMP_STEP;
  PetscCall(StepIncrements(d, s, "*COUPLED TEMPERATURE-DISPLACEMENT"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *STATIC: static equilibrium, the mechanical part alone, as the dialect runs it with coupled temperature-displacement
 * elements (and as CalculiX runs its mechanical decks): every temperature is held at its value at the step's start
 * (the initial conditions, or where the last step left it) unless the step prescribes it with *BOUNDARY on dof 11
 * or *TEMPERATURE; no heat transfer, so thermal loads are an error here (check.c). Solved as a steady step; loads
 * are ramped over it by default. */
static PetscErrorCode KwStatic(Deck *d, const DeckKeyword *kw)
{
  TslStep *s = &d->m->steps[d->step];

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!s->coupled, LOC_FMT "step %s already has a procedure", KLOC(d), s->name);
  USER_CHECK(!Param(d, "RIKS"), LOC_FMT "*STATIC, RIKS (the arc-length method) is not supported", KLOC(d));
  s->coupled = PETSC_TRUE;
  s->steady  = PETSC_TRUE;
  s->statik  = PETSC_TRUE;
  s->direct  = Param(d, "DIRECT") ? PETSC_TRUE : PETSC_FALSE;
  if (!s->amp_given) s->amp_default = TSL_AMP_RAMP;
  PetscCall(StepIncrements(d, s, "*STATIC"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *HEAT TRANSFER[, STEADY STATE][, DELTMX=][, DIRECT][, END=PERIOD | SS]: heat transfer alone, the temperature the
 * only unknown (a model of such steps only gets a temperature-only layout: DeckHeatTransferModel). Data line as
 * *COUPLED's (initial increment, period, minimum, maximum increment) and, with END=SS (Abaqus; transient only),
 * a fifth field: the temperature rate below which the step has reached its steady state and ends before its
 * period. CalculiX's FREQUENCY and MODAL DYNAMIC are not supported. */
static PetscErrorCode KwHeatTransfer(Deck *d, const DeckKeyword *kw)
{
  TslStep    *s = &d->m->steps[d->step];
  PetscBool   set, got;
  char        buf[32];
  const char *end = ParamUpper(d, "END", buf, sizeof(buf));

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!s->coupled, LOC_FMT "step %s already has a procedure", KLOC(d), s->name);
  USER_CHECK(!Param(d, "FREQUENCY") && !Param(d, "MODAL DYNAMIC"),
             LOC_FMT "*HEAT TRANSFER, FREQUENCY and MODAL DYNAMIC (eigenmodes) are not supported: transient or steady state only", KLOC(d));
  USER_CHECK(!end || !strcmp(end, "PERIOD") || !strcmp(end, "SS"), LOC_FMT "*HEAT TRANSFER, END=%s: END is PERIOD or SS", KLOC(d), end);
  s->coupled  = PETSC_TRUE;
  s->heat     = PETSC_TRUE;
  s->heat_loc = d->kwloc;
  s->steady  = Param(d, "STEADY STATE") ? PETSC_TRUE : PETSC_FALSE;
  s->direct  = Param(d, "DIRECT") ? PETSC_TRUE : PETSC_FALSE;
  USER_CHECK(!(end && !strcmp(end, "SS") && s->steady), LOC_FMT "*HEAT TRANSFER: END=SS ends a transient step; STEADY STATE has no rate to watch",
             KLOC(d));
  PetscCall(ParamReal(d, "DELTMX", &s->deltmx, &set));
  USER_CHECK(!set || s->deltmx >= 0, LOC_FMT "DELTMX must not be negative", KLOC(d));
  if (!s->amp_given) s->amp_default = s->steady ? TSL_AMP_RAMP : TSL_AMP_STEP;
  if (!end || strcmp(end, "SS")) {
    PetscCall(StepIncrements(d, s, "*HEAT TRANSFER"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* END=SS: the four fields of StepIncrements and the rate; the line is read here, StepIncrements reads none */
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*HEAT TRANSFER, END=SS needs a data line with the steady-state temperature rate in its fifth field", KLOC(d));
  USER_CHECK(d->nfield == 5,
             LOC_FMT "*HEAT TRANSFER, END=SS data line: initial increment, step period, minimum, maximum increment, steady-state temperature rate",
             DLOC(d));
  d->nfield = 4; /* the increments' fields alone, then the rate */
  PetscCall(StepIncrementFields(d, s, "*HEAT TRANSFER"));
  d->nfield = 5;
  PetscCall(FieldReal(d, 4, "the steady-state temperature rate", &s->end_ss_rate));
  USER_CHECK(s->end_ss_rate > 0, LOC_FMT "the steady-state temperature rate of END=SS must be positive (got %g)", DLOC(d), (double)s->end_ss_rate);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT (Abaqus/Explicit): data line "[increment], time period". The
 * increment is the stable one (element by element, times SCALE FACTOR) unless DIRECT USER CONTROL fixes it
 * to the first field. Only the explicit form exists here. */
static PetscErrorCode KwDynamic(Deck *d, const DeckKeyword *kw)
{
  TslStep  *s = &d->m->steps[d->step];
  PetscBool got, set, direct = Param(d, "DIRECT USER CONTROL") ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!s->coupled, LOC_FMT "step %s already has a procedure", KLOC(d), s->name);
  USER_CHECK(Param(d, "EXPLICIT"), LOC_FMT "*DYNAMIC TEMPERATURE-DISPLACEMENT is supported with EXPLICIT only (implicit dynamics is not available)",
             KLOC(d));
  s->coupled           = PETSC_TRUE;
  s->explicit_dynamics = PETSC_TRUE;
  s->dt_scale          = 1.0;
  PetscCall(ParamReal(d, "SCALE FACTOR", &s->dt_scale, &set));
  USER_CHECK(!set || (s->dt_scale > 0 && s->dt_scale <= 1), LOC_FMT "SCALE FACTOR must lie in (0, 1] (got %g)", KLOC(d), (double)s->dt_scale);
  if (!s->amp_given) s->amp_default = TSL_AMP_STEP;
  if (!s->bv_given) s->bv_linear = 0.06, s->bv_quadratic = 1.2; /* Abaqus/Explicit's defaults */
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(got, LOC_FMT "*DYNAMIC TEMPERATURE-DISPLACEMENT needs a data line: [time increment], time period", KLOC(d));
  USER_CHECK(d->nfield <= 2, LOC_FMT "*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT data line: [time increment], time period", DLOC(d));
  PetscCall(FieldRealDefault(d, 0, "the time increment", 0, &s->dt_user));
  PetscCall(FieldReal(d, 1, "the time period", &s->period));
  USER_CHECK(s->period > 0, LOC_FMT "the time period must be positive", DLOC(d));
  USER_CHECK(!direct || s->dt_user > 0, LOC_FMT "DIRECT USER CONTROL needs the time increment in the first field", DLOC(d));
  if (!direct) s->dt_user = 0; /* the first field is used only under DIRECT USER CONTROL, as in the dialect */
  s->dt0 = s->dtmax = s->period;
  s->dtmin          = 1e-5 * s->period;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *FIXED MASS SCALING, FACTOR=, DT=, ELSET=, TYPE=BELOW MIN and *VARIABLE MASS SCALING, DT=, ELSET=,
 * FREQUENCY=, TYPE=BELOW MIN: history data of an explicit step (checked in TslModelCheck). */
static PetscErrorCode KwMassScaling(Deck *d, const DeckKeyword *kw)
{
  TslStep        *s = &d->m->steps[d->step];
  TslMassScaling *ms;
  const char     *set = Param(d, "ELSET"), *type;
  char            buf[32];
  PetscBool       has_dt, has_f;

  PetscFunctionBeginUser;
  USER_CHECK(s->nmass < TSL_MAX_MASS_SCALING, LOC_FMT "at most %d mass scaling definitions per step", KLOC(d), TSL_MAX_MASS_SCALING);
  ms = &s->mass[s->nmass++];
  PetscCall(PetscMemzero(ms, sizeof(*ms)));
  ms->loc       = d->kwloc;
  ms->variable  = kw->kind ? PETSC_TRUE : PETSC_FALSE;
  ms->factor    = 1.0;
  ms->frequency = 1;
  if (set) PetscCall(CopyName(d, d->kwloc, ms->elset, set));
  PetscCall(ParamReal(d, "FACTOR", &ms->factor, &has_f));
  PetscCall(ParamReal(d, "DT", &ms->dt, &has_dt));
  PetscCall(ParamInt(d, "FREQUENCY", &ms->frequency));
  type = ParamUpper(d, "TYPE", buf, sizeof(buf));
  USER_CHECK(!type || !strcmp(type, "BELOW MIN"), LOC_FMT "*%s, TYPE=%s is not supported (BELOW MIN only)", KLOC(d), d->kw, type);
  USER_CHECK(ms->factor > 0, LOC_FMT "FACTOR must be positive (got %g)", KLOC(d), (double)ms->factor);
  USER_CHECK(!has_dt || ms->dt > 0, LOC_FMT "DT must be positive (got %g)", KLOC(d), (double)ms->dt);
  USER_CHECK(ms->frequency > 0, LOC_FMT "FREQUENCY must be positive", KLOC(d));
  USER_CHECK(!ms->variable || has_dt, LOC_FMT "*VARIABLE MASS SCALING needs DT= (the target element stable increment)", KLOC(d));
  USER_CHECK(ms->variable || has_dt || has_f, LOC_FMT "*FIXED MASS SCALING needs FACTOR= or DT=", KLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *BULK VISCOSITY: b1, b2 (linear and quadratic coefficients; a blank keeps the default 0.06 / 1.2).
 * History data of an explicit step (checked in TslModelCheck); only the linear term is applied. */
static PetscErrorCode KwBulkViscosity(Deck *d, const DeckKeyword *kw)
{
  TslStep  *s = &d->m->steps[d->step];
  PetscBool got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(!s->bv_given, LOC_FMT "*BULK VISCOSITY is given twice in step %s", KLOC(d), s->name);
  s->bv_given = PETSC_TRUE, s->bv_loc = d->kwloc;
  s->bv_linear = 0.06, s->bv_quadratic = 1.2;
  PetscCall(DataLine(d, 0, &got));
  if (got) {
    USER_CHECK(d->nfield <= 2, LOC_FMT "*BULK VISCOSITY takes b1, b2 (got %d values)", DLOC(d), (int)d->nfield);
    if (d->nfield > 0 && d->field[0][0]) PetscCall(FieldReal(d, 0, "the linear bulk viscosity b1", &s->bv_linear));
    if (d->nfield > 1 && d->field[1][0]) PetscCall(FieldReal(d, 1, "the quadratic bulk viscosity b2", &s->bv_quadratic));
    USER_CHECK(s->bv_linear >= 0 && s->bv_linear < 1, LOC_FMT "the linear bulk viscosity b1 must lie in [0, 1) (got %g)", DLOC(d), (double)s->bv_linear);
    USER_CHECK(s->bv_quadratic >= 0, LOC_FMT "the quadratic bulk viscosity b2 must not be negative (got %g)", DLOC(d), (double)s->bv_quadratic);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- loads ----------------------------------------------------------------------------------- */

static PetscErrorCode CheckDof(Deck *d, PetscInt dof)
{
  char buf[64];

  PetscFunctionBeginUser;
  USER_CHECK(ValidDof(d, dof), LOC_FMT "bad degree of freedom %" PetscInt_FMT " (valid: %s)", DLOC(d), dof, ValidDofList(d, buf, sizeof(buf)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* CalculiX's heat-transfer decks name the temperature dof 0 (its own internal number) in *BOUNDARY and *CFLUX: inside
 * a *HEAT TRANSFER step it is read as 11, and told once. */
static PetscErrorCode HeatDofZero(Deck *d, PetscInt *dof)
{
  PetscFunctionBeginUser;
  if (*dof != 0 || d->step < 0 || !d->m->steps[d->step].heat) PetscFunctionReturn(PETSC_SUCCESS);
  *dof = 11;
  if (!d->dof0_noted)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "note: degree of freedom 0 read as 11, the temperature (CalculiX's heat-transfer numbering)\n",
                          DLOC(d)));
  d->dof0_noted = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineBoundary(Deck *d, TslLoad *l)
{
  const char *f;
  char        up[32];
  PetscInt    dim = d->m->dim ? d->m->dim : 3;

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield >= 2 && d->nfield <= 4, LOC_FMT "*BOUNDARY data line needs: node or node set, first dof[, last dof[, value]]", DLOC(d));
  f = d->field[1];
  if (!IsInteger(f)) {
    (void)PetscStrncpy(up, f, sizeof(up));
    Normalize(up);
    if (!strcmp(up, "ENCASTRE") || !strcmp(up, "PINNED"))
      l->dof_first = 1, l->dof_last = PetscMin(3, dim);
    else if (!strcmp(up, "XSYMM"))
      l->dof_first = l->dof_last = 1;
    else if (!strcmp(up, "YSYMM"))
      l->dof_first = l->dof_last = 2;
    else if (!strcmp(up, "ZSYMM"))
      l->dof_first = l->dof_last = 3;
    else
      USER_ERR(LOC_FMT "bad degree of freedom '%s' (a number, ENCASTRE, PINNED, XSYMM, YSYMM or ZSYMM)", DLOC(d), f);
    USER_CHECK(d->nfield == 2, LOC_FMT "*BOUNDARY with %s takes no further values", DLOC(d), up);
    PetscCall(CheckDof(d, l->dof_last));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(FieldInt(d, 1, "the first dof", &l->dof_first));
  PetscCall(HeatDofZero(d, &l->dof_first));
  l->dof_last = l->dof_first;
  if (d->nfield > 2 && d->field[2][0]) PetscCall(FieldInt(d, 2, "the last dof", &l->dof_last));
  PetscCall(HeatDofZero(d, &l->dof_last));
  PetscCall(FieldRealDefault(d, 3, "the prescribed value", 0.0, &l->value));
  if (l->dof_first == 8 && l->dof_last == 8 && (d->pore || !d->m->nelem)) {
    /* the pore pressure of CPE4PT, ...: not active in the procedures thermoslide runs (docs/elements.md) */
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          LOC_FMT "warning: *BOUNDARY on dof 8 (pore pressure) is ignored: the pore pressure is not active in coupled "
                                  "temperature-displacement steps\n",
                          DLOC(d)));
    d->skip_line = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(CheckDof(d, l->dof_first));
  PetscCall(CheckDof(d, l->dof_last));
  /* a range may not run from a displacement into the temperature: 4..10 are no dofs */
  USER_CHECK(l->dof_first <= l->dof_last && (l->dof_last != 11 || l->dof_first == 11), LOC_FMT "bad dof range %" PetscInt_FMT "..%" PetscInt_FMT,
             DLOC(d), l->dof_first, l->dof_last);
  USER_CHECK(!l->velocity || l->dof_last != 11, LOC_FMT "*BOUNDARY, TYPE=VELOCITY applies to displacement dofs, not to the temperature (11)",
             DLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *TEMPERATURE (a predefined temperature field, as the dialect gives it to a *STATIC step): "node or node set,
 * temperature", read as the prescribed value of dof 11; only *STATIC steps take it (check.c). */
static PetscErrorCode LineTemperature(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 2, LOC_FMT "*TEMPERATURE data line needs: node or node set, temperature", DLOC(d));
  l->dof_first = l->dof_last = 11;
  l->temperature             = PETSC_TRUE;
  PetscCall(FieldReal(d, 1, "the temperature", &l->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineConcentrated(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 3, LOC_FMT "data line needs: node or node set, dof, magnitude", DLOC(d));
  PetscCall(FieldInt(d, 1, "the dof", &l->dof_first));
  if (l->kind == TSL_LOAD_CFLUX) PetscCall(HeatDofZero(d, &l->dof_first));
  l->dof_last = l->dof_first;
  if (l->kind == TSL_LOAD_CFLUX)
    USER_CHECK(l->dof_first == 11, LOC_FMT "bad degree of freedom %" PetscInt_FMT " for *CFLUX (must be 11)", DLOC(d), l->dof_first);
  else {
    PetscCall(CheckDof(d, l->dof_first));
    USER_CHECK(l->dof_first != 11, LOC_FMT "bad degree of freedom 11 for *CLOAD (use *CFLUX for heat)", DLOC(d));
  }
  PetscCall(FieldReal(d, 2, "the magnitude", &l->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Face label of a distributed load: prefix1..6 on elements, the bare prefix on a surface, BF (body flux) if allowed. */
static PetscErrorCode LoadFace(Deck *d, TslLoad *l, char prefix, PetscBool surface_only, PetscBool body)
{
  const char *f = d->field[1];

  PetscFunctionBeginUser;
  if (body && (f[0] == 'B' || f[0] == 'b') && (f[1] == 'F' || f[1] == 'f') && !f[2]) {
    USER_CHECK(!l->target.set[0] || TslModelFindSurface(d->m, l->target.set) < 0 || TslModelFindElementSet(d->m, l->target.set) >= 0,
               LOC_FMT "BF needs elements, not a surface", DLOC(d));
    l->face = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  l->face = FaceLabel(f, prefix);
  if (surface_only) USER_CHECK(l->face == 0, LOC_FMT "bad load label '%s' (expected %c with a surface)", DLOC(d), f, prefix);
  USER_CHECK(l->face >= 0, LOC_FMT "bad load label '%s' (expected %c1..%c6%s, or %c with a surface%s)", DLOC(d), f, prefix, prefix,
             body ? " or BF" : "", prefix,
             prefix == 'S'   ? ", or SPOS / SNEG on shells"
             : prefix == 'F' ? ", or FPOS / FNEG on shells"
             : prefix == 'R' ? ", or RPOS / RNEG on shells"
                             : "");
  if (l->face == 0) {
    USER_CHECK(l->target.set[0], LOC_FMT "label %c needs a surface name, not an element id", DLOC(d), prefix);
    l->target_is_surface = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *DLOAD's body-force labels, one row each: the values after the label (the magnitude first, then axis[]) and
 * where in axis[] the direction lies, which the reader normalises. Both dialects give a direction there: CalculiX
 * normalises it (a GRAV direction (0, 0, -2) gives the reactions of (0, 0, -1): ccx 2.20, measured), and Abaqus
 * reads "components of the gravity vector direction"; a direction without length is an error here (CalculiX runs
 * it into NaN). */
typedef struct {
  const char *label;
  TslDload    type;
  PetscInt    nvalue; /* values after the label */
  PetscInt    dir;    /* the direction's place in axis[] */
  PetscBool   square; /* the magnitude is a square (omega^2): not negative */
  const char *what;   /* the data line, for the message */
} DloadBody;

static const DloadBody dload_body[] = {
    {"GRAV", TSL_DLOAD_GRAV, 4, 0, PETSC_FALSE, "element or element set, GRAV, g, nx, ny, nz (the gravity direction)"},
    {"CENTRIF", TSL_DLOAD_CENTRIF, 7, 3, PETSC_TRUE,
     "element or element set, CENTRIF, omega^2, x0, y0, z0 (a point of the axis), ax, ay, az (its direction)"},
};

static PetscErrorCode LineDloadBody(Deck *d, TslLoad *l, const DloadBody *b)
{
  PetscReal len = 0;

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 2 + b->nvalue, LOC_FMT "*DLOAD %s data line needs %d values after the label (got %d): %s", DLOC(d), b->label,
             (int)b->nvalue, (int)(d->nfield - 2), b->what);
  l->dload = b->type;
  l->face  = 0;
  PetscCall(FieldReal(d, 2, "the magnitude", &l->value));
  USER_CHECK(!b->square || l->value >= 0, LOC_FMT "*DLOAD %s: omega^2 must not be negative (got %g)", DLOC(d), b->label, (double)l->value);
  for (PetscInt i = 0; i < b->nvalue - 1; i++) {
    USER_CHECK(d->field[3 + i][0], LOC_FMT "*DLOAD %s: value %d is blank: %s", DLOC(d), b->label, (int)(i + 2), b->what);
    PetscCall(FieldReal(d, 3 + i, "a coordinate", &l->axis[i]));
  }
  for (PetscInt i = 0; i < 3; i++) len += l->axis[b->dir + i] * l->axis[b->dir + i];
  len = PetscSqrtReal(len);
  USER_CHECK(len > 0, LOC_FMT "*DLOAD %s: the direction (%g, %g, %g) has no length", DLOC(d), b->label, (double)l->axis[b->dir],
             (double)l->axis[b->dir + 1], (double)l->axis[b->dir + 2]);
  for (PetscInt i = 0; i < 3; i++) l->axis[b->dir + i] /= len;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineDload(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  for (size_t k = 0; d->nfield >= 2 && k < sizeof(dload_body) / sizeof(dload_body[0]); k++)
    if (TslDeckNameEqual(d->field[1], dload_body[k].label)) {
      PetscCall(LineDloadBody(d, l, &dload_body[k]));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  USER_CHECK(d->nfield == 3,
             LOC_FMT "*DLOAD data line needs: element, element set or surface, P1..P6 or P, magnitude (or GRAV, CENTRIF: body forces)", DLOC(d));
  PetscCall(LoadFace(d, l, 'P', PETSC_FALSE, PETSC_FALSE));
  PetscCall(FieldReal(d, 2, "the magnitude", &l->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineDflux(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 3, LOC_FMT "*DFLUX data line needs: element or element set, S1..S6 or BF, magnitude", DLOC(d));
  PetscCall(LoadFace(d, l, 'S', PETSC_FALSE, PETSC_TRUE));
  PetscCall(FieldReal(d, 2, "the magnitude", &l->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The surface forms: *DSFLUX (surface, S, flux) and *DSLOAD (surface, P, pressure; Abaqus/CAE writes its
 * pressures so), *DLOAD's surface form. */
static PetscErrorCode LineSurfaceLoad(Deck *d, TslLoad *l, char label)
{
  const char *kw = label == 'S' ? "DSFLUX" : "DSLOAD";

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 3, LOC_FMT "*%s data line needs: surface, %c, magnitude", DLOC(d), kw, label);
  USER_CHECK(l->target.set[0], LOC_FMT "*%s needs a surface name", DLOC(d), kw);
  PetscCall(LoadFace(d, l, label, PETSC_TRUE, PETSC_FALSE));
  PetscCall(FieldReal(d, 2, "the magnitude", &l->value));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineDsflux(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  PetscCall(LineSurfaceLoad(d, l, 'S'));
  PetscFunctionReturn(PETSC_SUCCESS);
}
static PetscErrorCode LineDsload(Deck *d, TslLoad *l)
{
  PetscFunctionBeginUser;
  PetscCall(LineSurfaceLoad(d, l, 'P'));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LineFilm(Deck *d, TslLoad *l)
{
  PetscBool sfilm = d->kw[0] == 'S' ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  USER_CHECK(d->nfield == 4, LOC_FMT "*%s data line needs: %s, sink temperature, film coefficient", DLOC(d), d->kw,
             sfilm ? "surface, F" : "element, element set or surface, F1..F6 or F");
  if (sfilm) USER_CHECK(l->target.set[0], LOC_FMT "*SFILM needs a surface name", DLOC(d));
  PetscCall(LoadFace(d, l, 'F', sfilm, PETSC_FALSE));
  PetscCall(FieldReal(d, 2, "the sink temperature", &l->sink));
  PetscCall(FieldReal(d, 3, "the film coefficient", &l->value));
  USER_CHECK(l->value >= 0, LOC_FMT "the film coefficient must not be negative (got %g)", DLOC(d), (double)l->value);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *RADIATE (element or element set, R1..R6 / RPOS / RNEG, or surface, R) and *SRADIATE (surface, R): "target,
 * label, ambient temperature, emissivity" (the CalculiX manual's *RADIATE; Abaqus's *SRADIATE). The law works
 * in absolute temperature, so both physical constants must be given in the model data before the first step
 * (a deck without them would radiate on the wrong scale). Nonuniform (RxNU: a user subroutine) and cavity
 * radiation (RxCR: view factors between faces) are not modelled: errors, not a uniform radiation. */
static PetscErrorCode LineRadiate(Deck *d, TslLoad *l)
{
  const PetscBool sradiate = d->kw[0] == 'S' ? PETSC_TRUE : PETSC_FALSE;
  const char     *f        = d->field[1], *rest;

  PetscFunctionBeginUser;
  rest = f + (toupper((unsigned char)f[0]) == 'R' ? 1 : 0);
  if (*rest >= '0' && *rest <= '9') rest++;
  USER_CHECK(!(toupper((unsigned char)rest[0]) == 'N' && toupper((unsigned char)rest[1]) == 'U'),
             LOC_FMT "nonuniform radiation (label %s: the emissivity and ambient temperature from a user subroutine) is not supported", DLOC(d), f);
  USER_CHECK(!(toupper((unsigned char)rest[0]) == 'C' && toupper((unsigned char)rest[1]) == 'R'),
             LOC_FMT "cavity radiation (label %s: view factors between faces) is not supported (Rx radiates to an ambient temperature)", DLOC(d), f);
  USER_CHECK(d->nfield == 4, LOC_FMT "*%s data line needs: %s, ambient temperature, emissivity", DLOC(d), d->kw,
             sradiate ? "surface, R" : "element, element set or surface, R1..R6 or R");
  /* CalculiX writes a surface's label with the face number zero (R0; ccx 2.20 refuses a bare R there) */
  if ((f[1] == '0') && !f[2] && toupper((unsigned char)f[0]) == 'R') d->field[1][1] = 0;
  if (sradiate) USER_CHECK(l->target.set[0], LOC_FMT "*SRADIATE needs a surface name", DLOC(d));
  USER_CHECK(d->m->has_absolute_zero && d->m->has_stefan_boltzmann,
             LOC_FMT "*%s needs *PHYSICAL CONSTANTS with ABSOLUTE ZERO= and STEFAN BOLTZMANN= in the model data (missing: %s)", KLOC(d), d->kw,
             !d->m->has_absolute_zero && !d->m->has_stefan_boltzmann ? "both"
             : !d->m->has_absolute_zero                              ? "ABSOLUTE ZERO"
                                                                     : "STEFAN BOLTZMANN");
  PetscCall(LoadFace(d, l, 'R', sradiate, PETSC_FALSE));
  PetscCall(FieldReal(d, 2, "the ambient temperature", &l->sink));
  PetscCall(FieldReal(d, 3, "the emissivity", &l->value));
  USER_CHECK(l->value > 0 && l->value <= 1, LOC_FMT "the emissivity must lie in (0, 1] (got %g)", DLOC(d), (double)l->value);
  USER_CHECK(l->sink >= d->m->absolute_zero, LOC_FMT "the ambient temperature %g lies below absolute zero (%g, *PHYSICAL CONSTANTS)", DLOC(d),
             (double)l->sink, (double)d->m->absolute_zero);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AmplitudeParam(Deck *d, const char *key, PetscInt *index)
{
  const char *a = Param(d, key);

  PetscFunctionBeginUser;
  *index = -1;
  if (!a) PetscFunctionReturn(PETSC_SUCCESS);
  *index = TslModelFindAmplitude(d->m, a);
  USER_CHECK(*index >= 0, LOC_FMT "undefined amplitude %s", KLOC(d), a);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A load keyword in the model data (only *BOUNDARY may be there) prescribes dofs from the first step on, its
 * lines prepended to that step's (DeckModelLoads). A nonzero value is read as CalculiX's reader takes it (its
 * manual: "inhomogeneous conditions can be defined between a *STEP card and an *END STEP card only"; Abaqus
 * reads zero values only): the first step's, under that step's default amplitude. Nothing that needs a step
 * (an amplitude, OP=NEW, FIXED at the step's start values) is allowed. */
static PetscErrorCode ModelLoadCheck(Deck *d, const char *op)
{
  static const char *history_only[] = {"AMPLITUDE", "FIXED"};

  PetscFunctionBeginUser;
  USER_CHECK(!op || strcmp(op, "NEW"), LOC_FMT "*%s, OP=NEW in the model data: OP=NEW removes earlier conditions, so it belongs in a step", KLOC(d),
             d->kw);
  for (size_t i = 0; i < sizeof(history_only) / sizeof(history_only[0]); i++)
    USER_CHECK(!Param(d, history_only[i]), LOC_FMT "*%s, %s is history data: give this *%s inside a step", KLOC(d), d->kw, history_only[i], d->kw);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwLoad(Deck *d, const DeckKeyword *kw)
{
  PetscBool   model = d->step < 0 ? PETSC_TRUE : PETSC_FALSE; /* placement: model data (before the first *STEP) */
  TslLoad   **loads = model ? &d->mload : &d->m->steps[d->step].loads;
  PetscInt   *nload = model ? &d->nmload : &d->m->steps[d->step].nload;
  char        buf[16];
  const char *op = ParamUpper(d, "OP", buf, sizeof(buf));
  PetscInt    amp, famp, nline = 0;
  PetscBool   got;

  PetscFunctionBeginUser;
  USER_CHECK(!op || !strcmp(op, "NEW") || !strcmp(op, "MOD"), LOC_FMT "OP=%s: expected NEW or MOD", KLOC(d), op);
  char        tb[32];
  const char *type     = ParamUpper(d, "TYPE", tb, sizeof(tb));
  PetscBool   velocity = (PetscBool)(type && !strcmp(type, "VELOCITY"));
  /* *BOUNDARY, TYPE=VELOCITY: the dof follows the velocity's time integral (read as a displacement, a
   * velocity would move the body by its values); ACCELERATION is not supported */
  USER_CHECK(!type || velocity || !strcmp(type, "DISPLACEMENT"), LOC_FMT "*BOUNDARY, TYPE=%s is not supported (DISPLACEMENT or VELOCITY)", KLOC(d),
             type);
  USER_CHECK(!velocity || !model,
             LOC_FMT "*BOUNDARY, TYPE=VELOCITY belongs to a step (in the model data a boundary condition prescribes displacements)", KLOC(d));
  USER_CHECK(!velocity || !Param(d, "FIXED"), LOC_FMT "*BOUNDARY: FIXED and TYPE=VELOCITY exclude each other", KLOC(d));
  if (model) PetscCall(ModelLoadCheck(d, op));
  PetscCall(AmplitudeParam(d, "AMPLITUDE", &amp));
  PetscCall(AmplitudeParam(d, kw->kind == TSL_LOAD_RADIATE ? "RADIATION AMPLITUDE" : "FILM AMPLITUDE", &famp));
  for (;;) {
    TslLoad l;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    PetscCall(PetscMemzero(&l, sizeof(l)));
    l.kind           = (TslLoadKind)kw->kind;
    l.amplitude      = amp;
    l.film_amplitude = famp;
    l.op_new         = (op && !strcmp(op, "NEW")) ? PETSC_TRUE : PETSC_FALSE;
    l.fixed          = Param(d, "FIXED") ? PETSC_TRUE : PETSC_FALSE;
    l.velocity       = velocity;
    l.loc            = d->loc;
    USER_CHECK(d->nfield >= 2, LOC_FMT "*%s data line is too short", DLOC(d), d->kw);
    PetscCall(ParseTarget(d, d->field[0], kw->kind <= TSL_LOAD_CFLUX ? PETSC_TRUE : PETSC_FALSE, &l.target));
    PetscCall(kw->line(d, &l));
    if (d->skip_line) {
      d->skip_line = PETSC_FALSE;
      continue;
    }
    PetscCall(TslDeckGrow(loads, sizeof(TslLoad), *nload));
    (*loads)[(*nload)++] = l;
    nline++;
  }
  /* "*CLOAD, OP=NEW" alone removes every earlier load of its kind: keep it as a load without target */
  if (!nline && op && !strcmp(op, "NEW")) {
    TslLoad l;
    PetscCall(PetscMemzero(&l, sizeof(l)));
    l.kind           = (TslLoadKind)kw->kind;
    l.target.id      = -1;
    l.amplitude      = -1;
    l.film_amplitude = -1;
    l.op_new         = PETSC_TRUE;
    l.loc            = d->kwloc;
    PetscCall(TslDeckGrow(loads, sizeof(TslLoad), *nload));
    (*loads)[(*nload)++] = l;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *TEMPERATURE: node lines (KwLoad, LineTemperature), or FILE=job (sequential coupling, TslTemperatureFile): the
 * temperatures of an earlier job's results at every node, from the frames BSTEP, BINC .. ESTEP, EINC. The file is
 * job.h5 (".h5" added when missing), found relative to the working directory, else to the deck file's directory; it
 * is checked against the model (the same nodes) and read where the step starts (src/physics/tfile.c). */
static PetscErrorCode KwTemperature(Deck *d, const DeckKeyword *kw)
{
  const char         *file = Param(d, "FILE"), *from = d->m->files[d->kwloc.file], *slash;
  TslTemperatureFile *tf;
  char                name[PETSC_MAX_PATH_LEN], path[PETSC_MAX_PATH_LEN];
  PetscBool           got, found = PETSC_FALSE;
  size_t              len;

  PetscFunctionBeginUser;
  if (!file) {
    static const char *only_file[] = {"BSTEP", "BINC", "ESTEP", "EINC", "INTERPOLATE"};
    for (size_t i = 0; i < sizeof(only_file) / sizeof(only_file[0]); i++)
      USER_CHECK(!Param(d, only_file[i]), LOC_FMT "*TEMPERATURE, %s= belongs to the FILE= form (temperatures read from an earlier job's results)",
                 KLOC(d), only_file[i]);
    PetscCall(KwLoad(d, kw));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  USER_CHECK(d->step >= 0, LOC_FMT "*TEMPERATURE, FILE= belongs to a step", KLOC(d));
  USER_CHECK(file[0], LOC_FMT "*TEMPERATURE, FILE= needs the earlier job's name (its results job.h5)", KLOC(d));
  USER_CHECK(!Param(d, "INTERPOLATE"), LOC_FMT "*TEMPERATURE, FILE=, INTERPOLATE (temperatures mapped from another mesh) is not supported: "
             "the earlier job must have the same nodes", KLOC(d));
  USER_CHECK(!Param(d, "OP") || !strcmp(Param(d, "OP"), "MOD") || !strcmp(Param(d, "OP"), "mod"),
             LOC_FMT "*TEMPERATURE, FILE= sets every node's temperature: OP=NEW does not apply", KLOC(d));
  tf = &d->m->steps[d->step].tfile;
  USER_CHECK(!tf->given, LOC_FMT "a second *TEMPERATURE, FILE= in step %s (the first at line %" PetscInt_FMT ")", KLOC(d), d->m->steps[d->step].name,
             tf->loc.line);
  PetscCall(PetscMemzero(tf, sizeof(*tf)));
  tf->given = PETSC_TRUE;
  tf->loc   = d->kwloc;
  PetscCall(ParamInt(d, "BSTEP", &tf->bstep));
  PetscCall(ParamInt(d, "BINC", &tf->binc));
  PetscCall(ParamInt(d, "ESTEP", &tf->estep));
  PetscCall(ParamInt(d, "EINC", &tf->einc));
  USER_CHECK(tf->bstep >= 0 && tf->binc >= 0 && tf->estep >= 0 && tf->einc >= 0, LOC_FMT "*TEMPERATURE, FILE=: BSTEP, BINC, ESTEP and EINC are "
             "step and increment numbers (1, 2, ...)", KLOC(d));
  if (!tf->bstep) tf->bstep = 1;
  if (!tf->estep) tf->estep = tf->bstep;
  USER_CHECK(tf->estep > tf->bstep || (tf->estep == tf->bstep && (!tf->einc || !tf->binc || tf->einc >= tf->binc)),
             LOC_FMT "*TEMPERATURE, FILE=: the end (ESTEP %" PetscInt_FMT ", EINC %" PetscInt_FMT ") comes before the beginning (BSTEP %" PetscInt_FMT
             ", BINC %" PetscInt_FMT ")", KLOC(d), tf->estep, tf->einc, tf->bstep, tf->binc);
  PetscCall(AmplitudeParam(d, "AMPLITUDE", &tf->amplitude));
  len = strlen(file);
  USER_CHECK(len + 4 < sizeof(name), LOC_FMT "*TEMPERATURE, FILE=: the name is too long", KLOC(d));
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s%s", file, len > 3 && !strcmp(file + len - 3, ".h5") ? "" : ".h5"));
  USER_CHECK(!(len > 4 && (!strcmp(file + len - 4, ".odb") || !strcmp(file + len - 4, ".fil") || !strcmp(file + len - 4, ".frd"))),
             LOC_FMT "*TEMPERATURE, FILE=%s: thermoslide reads its own results (job or job.h5), not another code's", KLOC(d), file);
  /* the working directory first, then the deck file's directory */
  PetscCall(PetscTestFile(name, 'r', &found));
  if (found) PetscCall(PetscStrncpy(path, name, sizeof(path)));
  slash = strrchr(from, '/');
  if (!found && name[0] != '/' && slash) {
    PetscCall(PetscSNPrintf(path, sizeof(path), "%.*s/%s", (int)(slash - from), from, name));
    PetscCall(PetscTestFile(path, 'r', &found));
  }
  USER_CHECK(found, LOC_FMT "*TEMPERATURE, FILE=%s: no results file %s (looked in the working directory%s)", KLOC(d), file, name,
             slash && name[0] != '/' ? " and the deck's directory" : "");
  PetscCall(PetscStrncpy(tf->path, path, sizeof(tf->path)));
  PetscCall(DataLine(d, 0, &got));
  USER_CHECK(!got, LOC_FMT "*TEMPERATURE, FILE= reads every node's temperature from the file: no data lines", DLOC(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- output requests ------------------------------------------------------------------------- */

static PetscErrorCode KwOutput(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  if (d->post_own) PetscFunctionReturn(PETSC_SUCCESS); /* a POST OUTPUT deck: its frames are the points named, whatever the intervals */
  PetscInt *freq = d->step >= 0 ? &d->out_frequency : &d->out_frequency_model; /* model data: every step's default */

  *freq = 1;
  PetscCall(ParamInt(d, "FREQUENCY", freq));
  USER_CHECK(*freq >= 0, LOC_FMT "FREQUENCY must not be negative", KLOC(d));
  {
    /* Abaqus/CAE writes VARIABLE=PRESELECT: the default variables, which are what the outputs hold without a
     * *NODE OUTPUT / *ELEMENT OUTPUT (docs/output.md); any other value is read and ignored, with a warning */
    char        buf[16];
    const char *v = ParamUpper(d, "VARIABLE", buf, sizeof(buf));
    if (v && strcmp(v, "PRESELECT"))
      PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "warning: *OUTPUT, VARIABLE=%s is ignored (the default variables are written)\n", KLOC(d), v));
  }
  if (Param(d, "NUMBER INTERVAL") || Param(d, "TIME INTERVAL")) {
    /* frames at n equal intervals of the step or every dt of step time, the increments ending there (implicit
     * and explicit steps alike: src/solve/driver.c, TslFrameTimes); in the model data, every step's default */
    TslStep   *s      = d->step >= 0 ? &d->m->steps[d->step] : NULL;
    PetscInt  *number = s ? &s->out_number_interval : &d->out_number_model;
    PetscReal *time   = s ? &s->out_time_interval : &d->out_time_model;
    PetscBool  set;
    USER_CHECK(!(Param(d, "NUMBER INTERVAL") && Param(d, "TIME INTERVAL")) && !Param(d, "FREQUENCY"),
               LOC_FMT "*OUTPUT: FREQUENCY=, NUMBER INTERVAL= and TIME INTERVAL= exclude each other", KLOC(d));
    *number = 0, *time = 0; /* the one given replaces the other */
    PetscCall(ParamInt(d, "NUMBER INTERVAL", number));
    PetscCall(ParamReal(d, "TIME INTERVAL", time, &set));
    USER_CHECK(!Param(d, "NUMBER INTERVAL") || *number > 0, LOC_FMT "NUMBER INTERVAL must be positive (got %" PetscInt_FMT ")", KLOC(d), *number);
    USER_CHECK(!set || *time > 0, LOC_FMT "TIME INTERVAL must be positive (got %g)", KLOC(d), (double)*time);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define OUT_NODE  1
#define OUT_PRINT 2

static PetscErrorCode KwOutputRequest(Deck *d, const DeckKeyword *kw)
{
  TslStep          *s = d->post_own ? NULL : &d->m->steps[d->step];
  TslOutputRequest *r, **out = s ? &s->out : &d->m->post_out; /* a POST OUTPUT deck's own: the recovered frames' fields */
  PetscInt         *nout = s ? &s->nout : &d->m->npost_out;
  PetscBool         node = (kw->kind & OUT_NODE) ? PETSC_TRUE : PETSC_FALSE, got;
  const char       *key = node ? "NSET" : "ELSET", *set = Param(d, key);

  PetscFunctionBeginUser;
  USER_CHECK(!d->post_own || !(kw->kind & OUT_PRINT),
             LOC_FMT "*%s in a POST OUTPUT deck: its frames take field output requests (*NODE OUTPUT, *ELEMENT OUTPUT, *NODE FILE, *EL FILE); "
                     "printed tables are not recovered from restart points",
             KLOC(d), d->kw);
  if (kw->kind & OUT_PRINT) PetscCall(ParamRequired(d, key, &set));
  PetscCall(TslDeckGrow(out, sizeof(TslOutputRequest), *nout));
  r            = &(*out)[(*nout)++];
  r->node      = node;
  r->print     = (kw->kind & OUT_PRINT) ? PETSC_TRUE : PETSC_FALSE;
  r->loc       = d->kwloc;
  r->frequency = d->out_frequency;
  PetscCall(ParamInt(d, "FREQUENCY", &r->frequency));
  if (r->print) {
    char        buf[16];
    const char *t = ParamUpper(d, "TOTALS", buf, sizeof(buf));
    USER_CHECK(!t || !strcmp(t, "YES") || !strcmp(t, "NO") || !strcmp(t, "ONLY"), LOC_FMT "*%s, TOTALS=%s: expected YES, NO or ONLY", KLOC(d), d->kw,
               t);
    r->totals = !t || !strcmp(t, "NO") ? 0 : !strcmp(t, "YES") ? 1 : 2;
  }
  if (set) PetscCall(CopyName(d, d->kwloc, r->set, set));
  for (;;) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    for (PetscInt i = 0; i < d->nfield; i++) {
      char *v = Normalize(d->field[i]);
      if (!v[0]) continue;
      USER_CHECK(strlen(v) < sizeof(r->var[0]), LOC_FMT "output variable name %s is too long", DLOC(d), v);
      USER_CHECK(r->nvar < (PetscInt)(sizeof(r->var) / sizeof(r->var[0])), LOC_FMT "too many output variables (at most 16)", DLOC(d));
      PetscCall(PetscStrncpy(r->var[r->nvar++], v, sizeof(r->var[0])));
    }
  }
  if (!r->nvar && !r->print) { /* no data line: CalculiX's defaults (*NODE FILE U; *EL FILE S and E), not a frame of nothing */
    PetscCall(PetscStrncpy(r->var[r->nvar++], node ? "U" : "S", sizeof(r->var[0])));
    if (!node) PetscCall(PetscStrncpy(r->var[r->nvar++], "E", sizeof(r->var[0])));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *PARAMETER (Abaqus): data lines "name = expression" (expr.c), each name's value substituted for <name> in
 * every later line (Substitute). A name defined again takes the new value from there on. */
static PetscErrorCode KwParameter(Deck *d, const DeckKeyword *kw)
{
  const char *s;
  PetscBool   got;

  PetscFunctionBeginUser;
  (void)kw;
  for (;;) {
    char         *name, *expr, *eq, undefined[TSL_NAME_LEN];
    PetscReal     value;
    PetscInt      k;
    TslExprStatus status;
    PetscCall(RawNext(d, &s, &got));
    if (!got) break;
    if (IsKeywordLine(s)) {
      RawUnget(d);
      break;
    }
    PetscCall(BufReserve(&d->buf, &d->bufcap, strlen(s) + 1));
    memcpy(d->buf, s, strlen(s) + 1);
    eq = strchr(d->buf, '=');
    USER_CHECK(eq, LOC_FMT "*PARAMETER data line needs: name = expression", DLOC(d));
    *eq  = 0;
    name = Trim(d->buf);
    expr = Trim(eq + 1);
    USER_CHECK(TslDeckIsIdentifierStart(name[0]), LOC_FMT "*PARAMETER: '%s' is not a parameter name (a letter or _, then letters, digits or _)",
               DLOC(d), name);
    for (const char *c = name; *c; c++)
      USER_CHECK(TslDeckIsIdentifierChar(*c), LOC_FMT "*PARAMETER: '%s' is not a parameter name (a letter or _, then letters, digits or _)", DLOC(d),
                 name);
    status = TslDeckEvaluate(expr, ParameterLookup, d, &value, undefined);
    USER_CHECK(status == TSL_EXPR_OK, LOC_FMT "*PARAMETER %s = %s: %s%s%s", DLOC(d), name, expr, TslDeckExprMessage(status),
               status == TSL_EXPR_UNDEFINED ? " " : "", status == TSL_EXPR_UNDEFINED ? undefined : "");
    k = ParameterFind(d, name);
    if (k < 0) {
      PetscCall(TslDeckGrow(&d->parameters, sizeof(DeckParameter), d->nparameter));
      k = d->nparameter++;
      PetscCall(CopyName(d, d->loc, d->parameters[k].name, name));
    }
    d->parameters[k].value = value;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *SOILS: the consolidation procedure (pore fluid flow) is not one thermoslide runs. */
static PetscErrorCode KwSoils(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  USER_ERR(LOC_FMT
           "*SOILS (coupled pore fluid diffusion and stress) is not supported: pore fluid flow is not modelled. The pore pressure "
           "types (CPE4PT, CPE4PHT, CPE4RPT, CPE4RPHT) run in *COUPLED TEMPERATURE-DISPLACEMENT steps, where their pore pressure is not active",
           KLOC(d));
}

/* A keyword read past with a warning; kind IGNORED_PORE_FLUID: the pore fluid's material data (*PERMEABILITY,
 * *POROUS BULK MODULI), which the pore pressure types do not use in coupled temperature-displacement steps. */
#define IGNORED_PORE_FLUID 1
static PetscErrorCode KwIgnored(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  PetscCall(ReadPast(d, NULL, kw->kind == IGNORED_PORE_FLUID ? PORE_FLUID_NOTE : NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The old job a restart or POST OUTPUT deck names with -oldjob DIR/JOB (what names the keyword in messages): its
 * name in job, its directory in dir, and its deck copy DIR/JOB.restart.inp in copy, which must be there. */
static PetscErrorCode OldJob(Deck *d, const char *what, char job[], char dir[], char copy[])
{
  PetscBool   set;
  const char *slash;

  PetscFunctionBeginUser;
  job[0] = 0;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-oldjob", job, PETSC_MAX_PATH_LEN, &set));
  USER_CHECK(set && job[0], LOC_FMT "%s continues an old job: name it with -oldjob DIR/JOB (its output directory and job name)", KLOC(d), what);
  slash = strrchr(job, '/');
  USER_CHECK(!slash || slash[1], LOC_FMT "-oldjob %s names a directory, not a job: give DIR/JOB", KLOC(d), job);
  if (slash) {
    PetscCall(PetscStrncpy(dir, job, (size_t)(slash - job) + 1));
    if (!dir[0]) PetscCall(PetscStrncpy(dir, "/", PETSC_MAX_PATH_LEN));
  } else PetscCall(PetscStrncpy(dir, ".", PETSC_MAX_PATH_LEN));
  PetscCall(PetscSNPrintf(copy, PETSC_MAX_PATH_LEN + 64, "%s.restart.inp", job));
  USER_CHECK(!access(copy, R_OK), LOC_FMT "%s: the old job's deck copy %s is not there (a job keeps one beside its points when its deck has *RESTART, WRITE)",
             KLOC(d), what, copy);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The old job's restart point of step s, increment *inc (0: the latest of the step, set here), which must be there;
 * the error names the step's points. loc: the line to name (a keyword's or a data line's). */
static PetscErrorCode OldPoint(Deck *d, TslLoc loc, const char *what, const char *job, const char *dir, PetscInt s, PetscInt *inc)
{
  const char *slash = strrchr(job, '/'), *base = slash ? slash + 1 : job;
  char        pfx[PETSC_MAX_PATH_LEN + 64], have[256] = "";
  size_t      nh = 0;
  PetscInt    found = -1, latest = -1, incs[32], ninc = 0, want = *inc;
  DIR        *dp;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(pfx, sizeof(pfx), "%s.restart.%" PetscInt_FMT ".", base, s));
  dp = opendir(dir);
  USER_CHECK(dp, LOC_FMT "%s: cannot open the old job's directory %s: %s", TSL_LOC_ARGS(d->m, loc), what, dir, strerror(errno));
  for (struct dirent *e; (e = readdir(dp));) {
    long long i;
    int       n = 0;
    if (strncmp(e->d_name, pfx, strlen(pfx)) || sscanf(e->d_name + strlen(pfx), "%lld.h5%n", &i, &n) != 1 || e->d_name[strlen(pfx) + n]) continue;
    if ((PetscInt)i == want) found = want;
    latest = PetscMax(latest, (PetscInt)i);
    if (ninc < 32) incs[ninc++] = (PetscInt)i;
  }
  closedir(dp);
  PetscCall(PetscSortInt(ninc, incs)); /* the first 32 the directory lists, in order */
  for (PetscInt k = 0; k < ninc; k++) nh += (size_t)snprintf(have + nh, sizeof(have) - nh, "%s%" PetscInt_FMT, k ? ", " : "", incs[k]);
  if (!want) found = latest;
  if (want) {
    USER_CHECK(found >= 0, LOC_FMT "%s, STEP=%" PetscInt_FMT ", INC=%" PetscInt_FMT ": the old job %s wrote no restart point there (%s%s)", TSL_LOC_ARGS(d->m, loc), what, s,
               want, job, nh ? "its points of that step: increments " : "none in that step", have);
  } else
    USER_CHECK(found >= 0, LOC_FMT "%s, STEP=%" PetscInt_FMT ": the old job %s wrote no restart point there (none in that step)", TSL_LOC_ARGS(d->m, loc), what, s, job);
  *inc = found;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A restart or POST OUTPUT deck takes its model from the old job: its keyword comes first (after a *HEADING). */
static PetscErrorCode OldJobFirst(Deck *d, const char *what)
{
  const TslModel *m = d->m;

  PetscFunctionBeginUser;
  USER_CHECK(!m->nnode && !m->nelem && !m->nmaterial && d->step < 0 && !m->nstep && !m->restart_read_step && !m->post_output, LOC_FMT
             "%s comes first in its deck (after *HEADING), before any model data or step: the model is the old job's", KLOC(d), what);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *RESTART, READ, STEP=s [, INC=i] [, END STEP] (a restart deck, run with -oldjob DIR/JOB): first in the deck (after a
 * *HEADING), it reads the old job's deck copy DIR/JOB.restart.inp in its place, up to the end of its step s; the job
 * continues from the old job's point of step s, increment i (default: the latest written in that step), then runs
 * this deck's steps (src/solve/restart.c; docs/running.md "Restart"). */
static PetscErrorCode RestartRead(Deck *d)
{
  TslModel *m = d->m;
  PetscInt  s = 0, inc = 0;
  char      job[PETSC_MAX_PATH_LEN], dir[PETSC_MAX_PATH_LEN], copy[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBeginUser;
  PetscCall(OldJobFirst(d, "*RESTART, READ"));
  PetscCall(OldJob(d, "*RESTART, READ", job, dir, copy));
  USER_CHECK(Param(d, "STEP"), LOC_FMT "*RESTART, READ needs STEP= (the old job's step to continue from)", KLOC(d));
  PetscCall(ParamInt(d, "STEP", &s));
  PetscCall(ParamInt(d, "INC", &inc));
  USER_CHECK(s >= 1 && inc >= 0, LOC_FMT "*RESTART, READ: STEP must be 1 or more and INC not negative (got STEP=%" PetscInt_FMT ", INC=%" PetscInt_FMT ")", KLOC(d), s, inc);
  PetscCall(OldPoint(d, d->kwloc, "*RESTART, READ", job, dir, s, &inc));
  m->restart_read_step     = s;
  m->restart_read_inc      = inc;
  m->restart_read_end_step = (PetscBool)(Param(d, "END STEP") != NULL);
  m->restart_read_loc      = d->kwloc;
  PetscCall(PetscStrncpy(m->restart_read_job, job, sizeof(m->restart_read_job)));
  if (d->record) d->flatlen = d->flat_kw, d->flat[d->flatlen] = 0; /* this job's copy holds the old deck in its place */
  PetscCall(DeckOpen(d, copy, PETSC_TRUE));
  d->restart_stop  = s;
  d->restart_depth = d->depth;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *POST OUTPUT [, ALL] with data lines "step, increment" (a POST OUTPUT deck, run with -oldjob DIR/JOB): a frame of each
 * restart point named (ALL: of every point the old job wrote), recovered from the point's state with the output
 * requests of its step in the old job's deck, which is read in this keyword's place (src/solve/restart.c,
 * TslRestartPostOutput). The deck holds nothing else but a *HEADING. */
static PetscErrorCode KwPostOutput(Deck *d, const DeckKeyword *kw)
{
  TslModel *m = d->m;
  char      job[PETSC_MAX_PATH_LEN], dir[PETSC_MAX_PATH_LEN], copy[PETSC_MAX_PATH_LEN + 64];
  PetscBool got;

  PetscFunctionBeginUser;
  (void)kw;
  PetscCall(OldJobFirst(d, "*POST OUTPUT"));
  PetscCall(OldJob(d, "*POST OUTPUT", job, dir, copy));
  m->post_output      = Param(d, "ALL") ? 2 : 1;
  m->restart_read_loc = d->kwloc;
  PetscCall(PetscStrncpy(m->restart_read_job, job, sizeof(m->restart_read_job)));
  for (;;) {
    PetscInt s, inc;
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    USER_CHECK(m->post_output == 1, LOC_FMT "*POST OUTPUT, ALL takes no data lines", DLOC(d));
    USER_CHECK(d->nfield == 2, LOC_FMT "*POST OUTPUT data line: step, increment", DLOC(d));
    PetscCall(FieldInt(d, 0, "the step", &s));
    PetscCall(FieldInt(d, 1, "the increment", &inc));
    USER_CHECK(s >= 1 && inc >= 1, LOC_FMT "*POST OUTPUT: the step and the increment must be 1 or more (got %" PetscInt_FMT ", %" PetscInt_FMT ")", DLOC(d), s, inc);
    PetscCall(OldPoint(d, d->loc, "*POST OUTPUT", job, dir, s, &inc));
    PetscCall(TslDeckGrow(&m->post, 2 * sizeof(PetscInt), m->npost));
    m->post[2 * m->npost] = s, m->post[2 * m->npost + 1] = inc, m->npost++;
  }
  USER_CHECK(m->post_output == 2 || m->npost, LOC_FMT "*POST OUTPUT needs data lines (step, increment) or ALL", KLOC(d));
  d->post_depth = d->depth; /* what follows the old job's deck in this one is this deck's own (CheckPlacement) */
  PetscCall(DeckOpen(d, copy, PETSC_TRUE)); /* the keyword line after the data lines is read after it (RawRewind) */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *RESTART, WRITE [, FREQUENCY=n] [, NUMBER INTERVAL=n] [, TIME MARKS=YES|NO] [, OVERLAY]: restart points every n
 * increments of this step and the ones after (until the next *RESTART), at n times evenly spaced over each step, and
 * at each step's end (src/solve/restart.c, TslRestartDue; docs/running.md "Restart"). Neither FREQUENCY nor NUMBER
 * INTERVAL: the dialect's defaults, every increment in implicit steps (Abaqus/Standard's FREQUENCY=1), the step's end
 * in explicit ones (Abaqus/Explicit's NUMBER INTERVAL=1). Model data: from the first step on. READ: RestartRead. */
static PetscErrorCode KwRestart(Deck *d, const DeckKeyword *kw)
{
  PetscInt freq = -1, nint = 0;

  PetscFunctionBeginUser;
  (void)kw;
  if (Param(d, "READ")) {
    PetscCall(RestartRead(d));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  USER_CHECK(Param(d, "WRITE"), LOC_FMT "*RESTART needs WRITE (or READ)", KLOC(d));
  PetscCall(ParamInt(d, "FREQUENCY", &freq));
  USER_CHECK(!Param(d, "FREQUENCY") || freq >= 0, LOC_FMT "*RESTART, FREQUENCY must not be negative (got %" PetscInt_FMT ")", KLOC(d), freq);
  PetscCall(ParamInt(d, "NUMBER INTERVAL", &nint));
  USER_CHECK(nint >= 0, LOC_FMT "*RESTART, NUMBER INTERVAL must not be negative (got %" PetscInt_FMT ")", KLOC(d), nint);
  if (Param(d, "NUMBER INTERVAL") && !Param(d, "FREQUENCY")) freq = 0; /* the intervals alone */
  /* TIME MARKS: whether the points fall exactly on the interval times; here a point is written at the first increment
   * that reaches each (the increments are not cut for it), as with TIME MARKS=NO */
  d->restart_frequency = freq;
  d->restart_interval  = nint;
  d->restart_overlay   = (PetscBool)(Param(d, "OVERLAY") != NULL);
  d->restart_loc       = d->kwloc;
  if (d->step >= 0) {
    TslStep *s           = &d->m->steps[d->step];
    s->restart_frequency = d->restart_frequency;
    s->restart_interval  = d->restart_interval;
    s->restart_overlay   = d->restart_overlay;
    s->restart_loc       = d->restart_loc;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *PART, NAME=p: the ids after it are shifted past every id defined so far (see "Parts and instances"). */
static PetscErrorCode KwPart(Deck *d, const DeckKeyword *kw)
{
  TslModel   *m = d->m;
  const char *name;
  DeckPart   *p;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->part < 0 && !d->assembly, LOC_FMT "*PART inside %s", KLOC(d), d->part >= 0 ? "another *PART (missing *END PART?)" : "the *ASSEMBLY");
  PetscCall(ParamRequired(d, "NAME", &name));
  for (PetscInt i = 0; i < d->npart; i++) USER_CHECK(!TslDeckNameEqual(d->parts[i].name, name), LOC_FMT "part %s is defined twice", KLOC(d), name);
  PetscCall(TslDeckGrow(&d->parts, sizeof(DeckPart), d->npart));
  p = &d->parts[d->npart];
  PetscCall(PetscMemzero(p, sizeof(*p)));
  PetscCall(CopyName(d, d->kwloc, p->name, name));
  p->node_off   = IdMax(m->node_id, m->nnode);
  p->elem_off   = IdMax(m->elem_id, m->nelem);
  p->node_first = m->nnode;
  p->elem_first = m->nelem;
  p->nsets[0] = m->nnset, p->nsets[1] = m->nelset, p->nsets[2] = m->nsurface;
  p->nsection = m->nsection;
  p->nt[0]    = m->nnodal_thickness;
  p->first    = -1;
  p->loc      = d->kwloc;
  d->part     = d->npart++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwEndPart(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->part >= 0, LOC_FMT "*END PART without *PART", KLOC(d));
  {
    DeckPart *p = &d->parts[d->part];
    p->node_n   = d->m->nnode - p->node_first;
    p->elem_n   = d->m->nelem - p->elem_first;
    p->nt[1]    = d->m->nnodal_thickness;
    PetscCall(PetscMalloc1(3 * p->node_n + 1, &p->xyz));
    PetscCall(PetscArraycpy(p->xyz, d->m->node_xyz + 3 * p->node_first, 3 * p->node_n));
  }
  d->part = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwAssembly(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->part < 0, LOC_FMT "*ASSEMBLY inside a *PART (missing *END PART?)", KLOC(d));
  USER_CHECK(!d->assembly, LOC_FMT "a second *ASSEMBLY (missing *END ASSEMBLY?)", KLOC(d));
  d->assembly     = PETSC_TRUE;
  d->assembly_loc = d->kwloc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwEndAssembly(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->assembly && d->instance < 0, LOC_FMT "*END ASSEMBLY %s", KLOC(d),
             d->assembly ? "inside an *INSTANCE (missing *END INSTANCE?)" : "without *ASSEMBLY");
  d->assembly = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A name qualified by prefix ("p.x") requalified by to ("i.x") into out; PETSC_FALSE if it is not prefix's. */
static PetscErrorCode Requalified(Deck *d, const char *prefix, const char *to, const char *name, char out[TSL_NAME_LEN], PetscBool *is)
{
  size_t n = strlen(prefix);
  char   buf[2 * TSL_NAME_LEN + 2];

  PetscFunctionBeginUser;
  *is = PETSC_FALSE;
  if (strlen(name) <= n || name[n] != '.' || strncmp(name, prefix, n)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(buf, sizeof(buf), "%s.%s", to, name + n + 1));
  PetscCall(CopyName(d, d->kwloc, out, buf));
  *is = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The first instance of part p: its names "p.x" become "i.x" in place. */
static PetscErrorCode RenameFirst(Deck *d, const DeckPart *p, const char *inst)
{
  TslModel *m = d->m;
  PetscBool is;

  PetscFunctionBeginUser;
  for (PetscInt i = p->nsets[0]; i < m->nnset; i++) PetscCall(Requalified(d, p->name, inst, m->nsets[i].name, m->nsets[i].name, &is));
  for (PetscInt i = p->nsets[1]; i < m->nelset; i++) PetscCall(Requalified(d, p->name, inst, m->elsets[i].name, m->elsets[i].name, &is));
  for (PetscInt i = p->nsets[2]; i < m->nsurface; i++) PetscCall(Requalified(d, p->name, inst, m->surfaces[i].name, m->surfaces[i].name, &is));
  for (PetscInt i = p->nsection; i < m->nsection; i++) {
    PetscCall(Requalified(d, p->name, inst, m->sections[i].elset, m->sections[i].elset, &is));
    PetscCall(Requalified(d, p->name, inst, m->sections[i].ref_node.set, m->sections[i].ref_node.set, &is));
  }
  for (PetscInt i = p->nt[0]; i < p->nt[1]; i++) {
    TslTarget *t = &m->nodal_thickness[i].target;
    if (t->set[0]) PetscCall(Requalified(d, p->name, inst, t->set, t->set, &is));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A copy of a set of the first instance (its ids shifted by dn) for instance "to" */
static PetscErrorCode CopySets(Deck *d, TslSet **sets, PetscInt *n, PetscInt from, PetscInt end, const char *first, const char *to, PetscInt shift)
{
  PetscFunctionBeginUser;
  for (PetscInt i = from; i < end; i++) {
    char      name[TSL_NAME_LEN];
    PetscBool is;
    PetscCall(Requalified(d, first, to, (*sets)[i].name, name, &is));
    if (!is) continue;
    PetscCall(TslDeckGrow(sets, sizeof(TslSet), *n));
    {
      TslSet *src = &(*sets)[i], *dst = &(*sets)[*n];
      *dst = *src;
      PetscCall(PetscStrncpy(dst->name, name, TSL_NAME_LEN));
      PetscCall(PetscMalloc1(src->n + 1, &dst->ids));
      for (PetscInt k = 0; k < src->n; k++) dst->ids[k] = src->ids[k] + shift;
      (*n)++;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A further instance of part p (first instance f): its nodes (at the part's own coordinates, then moved by
 * the caller), elements, sets, surfaces and sections copied with the instance's ids and names. */
static PetscErrorCode CopyInstance(Deck *d, const DeckPart *p, const DeckInstance *f, const DeckInstance *in)
{
  TslModel      *m  = d->m;
  const PetscInt dn = in->node_off - f->node_off, de = in->elem_off - f->elem_off;
  const PetscInt nset = m->nnset, nelset = m->nelset, nsurf = m->nsurface, nsec = m->nsection;

  PetscFunctionBeginUser;
  for (PetscInt k = p->node_first; k < p->node_first + p->node_n; k++) {
    PetscCall(TslDeckGrow(&m->node_id, sizeof(PetscInt), m->nnode));
    PetscCall(TslDeckGrow(&m->node_xyz, 3 * sizeof(PetscReal), m->nnode));
    PetscCall(TslDeckGrow(&d->node_line, 2 * sizeof(PetscInt), m->nnode));
    m->node_id[m->nnode] = m->node_id[k] + dn;
    for (PetscInt c = 0; c < 3; c++) m->node_xyz[3 * m->nnode + c] = p->xyz[3 * (k - p->node_first) + c];
    d->node_line[2 * m->nnode] = d->kwloc.file, d->node_line[2 * m->nnode + 1] = d->kwloc.line;
    m->nnode++;
  }
  for (PetscInt e = p->elem_first; e < p->elem_first + p->elem_n; e++) {
    PetscInt k, nn = m->elem_ptr[e + 1] - m->elem_ptr[e];
    PetscCall(TslDeckGrow(&m->elem_id, sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_type, sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_line, 2 * sizeof(PetscInt), m->nelem));
    PetscCall(TslDeckGrow(&m->elem_ptr, sizeof(PetscInt), m->nelem + 1));
    k = m->elem_ptr[m->nelem];
    for (PetscInt j = 0; j < nn; j++, k++) {
      PetscCall(TslDeckGrow(&m->elem_conn, sizeof(PetscInt), k));
      m->elem_conn[k] = m->elem_conn[m->elem_ptr[e] + j] + dn;
    }
    m->elem_id[m->nelem]           = m->elem_id[e] + de;
    m->elem_type[m->nelem]         = m->elem_type[e];
    m->elem_line[2 * m->nelem]     = m->elem_line[2 * e];
    m->elem_line[2 * m->nelem + 1] = m->elem_line[2 * e + 1];
    m->elem_ptr[++m->nelem]        = k;
  }
  PetscCall(CopySets(d, &m->nsets, &m->nnset, p->nsets[0], nset, f->name, in->name, dn));
  PetscCall(CopySets(d, &m->elsets, &m->nelset, p->nsets[1], nelset, f->name, in->name, de));
  for (PetscInt i = p->nsets[2]; i < nsurf; i++) {
    char      name[TSL_NAME_LEN];
    PetscBool is;
    PetscCall(Requalified(d, f->name, in->name, m->surfaces[i].name, name, &is));
    if (!is) continue;
    PetscCall(TslDeckGrow(&m->surfaces, sizeof(TslSurface), m->nsurface));
    {
      TslSurface    *src = &m->surfaces[i], *dst = &m->surfaces[m->nsurface];
      const PetscInt sh = src->kind == TSL_SURFACE_NODE ? dn : de;
      *dst              = *src;
      PetscCall(PetscStrncpy(dst->name, name, TSL_NAME_LEN));
      PetscCall(PetscMalloc1(src->n + 1, &dst->elem));
      for (PetscInt k = 0; k < src->n; k++) dst->elem[k] = src->elem[k] + sh;
      dst->face = NULL;
      if (src->face) {
        PetscCall(PetscMalloc1(src->n + 1, &dst->face));
        PetscCall(PetscArraycpy(dst->face, src->face, src->n));
      }
      m->nsurface++;
    }
  }
  for (PetscInt i = p->nsection; i < nsec; i++) {
    char      name[TSL_NAME_LEN];
    PetscBool is;
    PetscCall(Requalified(d, f->name, in->name, m->sections[i].elset, name, &is));
    if (!is) continue;
    PetscCall(TslDeckGrow(&m->sections, sizeof(TslSection), m->nsection));
    m->sections[m->nsection] = m->sections[i];
    PetscCall(PetscStrncpy(m->sections[m->nsection].elset, name, TSL_NAME_LEN));
    PetscCall(Requalified(d, f->name, in->name, m->sections[i].ref_node.set, m->sections[m->nsection].ref_node.set, &is));
    if (m->sections[i].ref_node.id >= 0) m->sections[m->nsection].ref_node.id += dn;
    m->nsection++;
  }
  for (PetscInt i = p->nt[0]; i < p->nt[1]; i++) { /* the part's nodal thicknesses, for this instance's nodes */
    TslNodalThickness *src, *dst;
    PetscBool          is = PETSC_TRUE;
    PetscCall(TslDeckGrow(&m->nodal_thickness, sizeof(TslNodalThickness), m->nnodal_thickness));
    src  = &m->nodal_thickness[i];
    dst  = &m->nodal_thickness[m->nnodal_thickness];
    *dst = *src;
    if (src->target.set[0])
      PetscCall(Requalified(d, f->name, in->name, src->target.set, dst->target.set, &is));
    else
      dst->target.id += dn;
    if (is) m->nnodal_thickness++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *INSTANCE, NAME=i, PART=p: the part placed. Its first instance renames its names "i.x"; a further one
 * copies it (CopyInstance). The optional data lines move its nodes: a translation, then a rotation by an angle
 * (degrees) about the axis through points a and b. */
static PetscErrorCode KwInstance(Deck *d, const DeckKeyword *kw)
{
  TslModel     *m = d->m;
  const char   *name, *part;
  DeckPart     *p = NULL;
  DeckInstance *in;
  PetscReal     t[3] = {0, 0, 0}, R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, a[3] = {0, 0, 0};
  PetscInt      first_node;
  PetscBool     got;

  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->assembly && d->instance < 0, LOC_FMT "*INSTANCE %s", KLOC(d),
             d->assembly ? "inside another *INSTANCE (missing *END INSTANCE?)" : "outside an *ASSEMBLY");
  PetscCall(ParamRequired(d, "NAME", &name));
  USER_CHECK(Param(d, "PART"), LOC_FMT "*INSTANCE needs PART= (an instance of a model given inline, or of another model, is not supported)", KLOC(d));
  PetscCall(ParamRequired(d, "PART", &part));
  USER_CHECK(InstanceFind(d, name) < 0, LOC_FMT "instance %s is defined twice", KLOC(d), name);
  for (PetscInt i = 0; i < d->npart; i++)
    if (TslDeckNameEqual(d->parts[i].name, part)) p = &d->parts[i];
  USER_CHECK(p, LOC_FMT "*INSTANCE, PART=%s: no such part", KLOC(d), part);
  PetscCall(TslDeckGrow(&d->inst, sizeof(DeckInstance), d->ninst));
  in = &d->inst[d->ninst];
  PetscCall(PetscMemzero(in, sizeof(*in)));
  PetscCall(CopyName(d, d->kwloc, in->name, name));
  in->part = (PetscInt)(p - d->parts);
  if (p->first < 0) { /* the first instance: the part as read */
    in->node_off = p->node_off, in->elem_off = p->elem_off;
    first_node = p->node_first;
    p->first   = d->ninst;
    PetscCall(RenameFirst(d, p, in->name));
  } else { /* a further one: its smallest ids follow the largest defined so far */
    in->node_off = p->node_off + IdMax(m->node_id, m->nnode) + 1 - IdMin(m->node_id + p->node_first, p->node_n);
    in->elem_off = p->elem_off + IdMax(m->elem_id, m->nelem) + 1 - IdMin(m->elem_id + p->elem_first, p->elem_n);
    first_node   = m->nnode;
    PetscCall(CopyInstance(d, p, &d->inst[p->first], in));
  }
  d->ninst++;
  for (PetscInt line = 0; line < 2; line++) {
    PetscCall(DataLine(d, 0, &got));
    if (!got) break;
    if (line == 0) {
      USER_CHECK(d->nfield <= 3, LOC_FMT "*INSTANCE translation line needs: x, y[, z]", DLOC(d));
      for (PetscInt c = 0; c < 3; c++) PetscCall(FieldRealDefault(d, c, "a translation", 0.0, &t[c]));
    } else {
      PetscReal b[3], u[3], len = 0, ang, cs, sn;
      USER_CHECK(d->nfield == 7, LOC_FMT "*INSTANCE rotation line needs: a1, a2, a3, b1, b2, b3, angle (degrees)", DLOC(d));
      for (PetscInt c = 0; c < 3; c++) {
        PetscCall(FieldReal(d, c, "a point of the axis", &a[c]));
        PetscCall(FieldReal(d, 3 + c, "a point of the axis", &b[c]));
        u[c] = b[c] - a[c], len += u[c] * u[c];
      }
      PetscCall(FieldReal(d, 6, "the angle", &ang));
      USER_CHECK(len > 0, LOC_FMT "*INSTANCE rotation: the axis needs two distinct points", DLOC(d));
      len = PetscSqrtReal(len);
      for (PetscInt c = 0; c < 3; c++) u[c] /= len;
      USER_CHECK(m->dim != 2 || ang == 0 || (PetscAbsReal(u[0]) < 1e-12 && PetscAbsReal(u[1]) < 1e-12),
                 LOC_FMT "*INSTANCE rotation of a 2D part must be about an axis along z", DLOC(d));
      ang *= PETSC_PI / 180, cs = PetscCosReal(ang), sn = PetscSinReal(ang);
      for (PetscInt i = 0; i < 3; i++) /* Rodrigues: R = cos I + sin [u]x + (1 - cos) u u^T */
        for (PetscInt j = 0; j < 3; j++) {
          const PetscReal cross[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
          R[i][j]                     = (i == j ? cs : 0) + sn * cross[i][j] + (1 - cs) * u[i] * u[j];
        }
    }
  }
  for (PetscInt k = first_node; k < first_node + p->node_n; k++) {
    PetscReal *x = &m->node_xyz[3 * k], y[3];
    for (PetscInt c = 0; c < 3; c++) y[c] = x[c] + t[c] - a[c];
    for (PetscInt c = 0; c < 3; c++) x[c] = a[c] + R[c][0] * y[0] + R[c][1] * y[1] + R[c][2] * y[2];
  }
  d->instance = d->ninst - 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KwEndInstance(Deck *d, const DeckKeyword *kw)
{
  PetscFunctionBeginUser;
  (void)kw;
  USER_CHECK(d->instance >= 0, LOC_FMT "*END INSTANCE without *INSTANCE", KLOC(d));
  d->instance = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define LOAD_PARAMS "OP|AMPLITUDE"
static const DeckKeyword Keywords[] = {
    {"HEADING", AT_MODEL, IN_NONE, "", KwHeading, 0, NULL},
    {"NODE", AT_MODEL, IN_NONE, "NSET", KwNode, 0, NULL},
    {"ELEMENT", AT_MODEL, IN_NONE, "TYPE|ELSET", KwElement, 0, NULL},
    {"NSET", AT_MODEL, IN_NONE, "NSET|GENERATE|INSTANCE|INTERNAL", KwSet, 0, NULL},
    {"ELSET", AT_MODEL, IN_NONE, "ELSET|GENERATE|INSTANCE|INTERNAL", KwSet, 1, NULL},
    {"SURFACE", AT_MODEL, IN_NONE, "NAME|TYPE|INTERNAL", KwSurface, 0, NULL},
    {"PART", AT_MODEL, IN_NONE, "NAME", KwPart, 0, NULL},
    {"END PART", AT_MODEL, IN_NONE, "", KwEndPart, 0, NULL},
    {"ASSEMBLY", AT_MODEL, IN_NONE, "NAME", KwAssembly, 0, NULL},
    {"END ASSEMBLY", AT_MODEL, IN_NONE, "", KwEndAssembly, 0, NULL},
    {"INSTANCE", AT_MODEL, IN_NONE, "NAME|PART", KwInstance, 0, NULL},
    {"END INSTANCE", AT_MODEL, IN_NONE, "", KwEndInstance, 0, NULL},
    {"MATERIAL", AT_MODEL, IN_NONE, "NAME", KwMaterial, 0, NULL},
    {"ELASTIC", AT_MODEL, IN_MATERIAL, "TYPE", KwProperty, TSL_PROP_ELASTIC, NULL},
    {"CONDUCTIVITY", AT_MODEL, IN_MATERIAL, "TYPE", KwProperty, TSL_PROP_CONDUCTIVITY, NULL},
    {"DENSITY", AT_MODEL, IN_MATERIAL, "", KwProperty, TSL_PROP_DENSITY, NULL},
    {"SPECIFIC HEAT", AT_MODEL, IN_MATERIAL, "", KwProperty, TSL_PROP_SPECIFIC_HEAT, NULL},
    {"EXPANSION", AT_MODEL, IN_MATERIAL, "TYPE|ZERO", KwProperty, TSL_PROP_EXPANSION, NULL},
    {"PLASTIC", AT_MODEL, IN_MATERIAL, "HARDENING|RATE|DATA TYPE|NUMBER BACKSTRESSES", KwPlastic, 0, NULL},
    {"INELASTIC HEAT FRACTION", AT_MODEL, IN_MATERIAL, "", KwInelasticHeatFraction, 0, NULL},
    {"DAMPING", AT_MODEL, IN_MATERIAL, "ALPHA|BETA|STRUCTURAL|COMPOSITE", KwDamping, 0, NULL},
    {"RATE DEPENDENT", AT_MODEL, IN_MATERIAL, "TYPE", KwRateDependent, 0, NULL},
    {"CYCLIC HARDENING", AT_MODEL, IN_MATERIAL, "PARAMETERS", KwCyclicHardening, 0, NULL},
    {"SOLID SECTION", AT_MODEL, IN_NONE, "ELSET|MATERIAL|REF NODE", KwSolidSection, 0, NULL},
    {"SHELL SECTION", AT_MODEL, IN_NONE,
     "ELSET|MATERIAL|THICKNESS MODULUS|STACK DIRECTION|SECTION INTEGRATION|POISSON|OFFSET|NODAL THICKNESS|COMPOSITE|DENSITY", KwShellSection, 0,
     NULL},
    {"NODAL THICKNESS", AT_MODEL, IN_NONE, "", KwNodalThickness, 0, NULL},
    {"INITIAL CONDITIONS", AT_MODEL, IN_NONE, "TYPE", KwInitial, 0, NULL},
    {"AMPLITUDE", AT_BOTH, IN_NONE, "NAME|TIME|DEFINITION|FIXED INTERVAL|BEGIN", KwAmplitude, 0, NULL},
    {"PHYSICAL CONSTANTS", AT_MODEL, IN_NONE, "ABSOLUTE ZERO|STEFAN BOLTZMANN", KwPhysical, 0, NULL},
    {"EQUATION", AT_MODEL, IN_NONE, "", KwEquation, 0, NULL},
    {"SURFACE INTERACTION", AT_MODEL, IN_NONE, "NAME", KwSurfaceInteraction, 0, NULL},
    {"SURFACE BEHAVIOR", AT_MODEL, IN_INTERACTION, "PRESSURE-OVERCLOSURE|PENALTY|AUGMENTED LAGRANGE|DIRECT|NO SEPARATION", KwSurfaceBehavior, 0,
     NULL},
    {"FRICTION", AT_MODEL, IN_INTERACTION, "LAGRANGE|ROUGH|SLIP TOLERANCE|ELASTIC SLIP", KwFriction, 0, NULL},
    {"GAP CONDUCTANCE", AT_MODEL, IN_INTERACTION, "PRESSURE|DEPENDENCIES|USER", KwGapConductance, 0, NULL},
    {"GAP RADIATION", AT_MODEL, IN_INTERACTION, "", KwGapRadiation, 0, NULL},
    {"GAP HEAT GENERATION", AT_MODEL, IN_INTERACTION, "USER", KwGapHeatGeneration, 0, NULL},
    {"CONTACT PAIR", AT_MODEL, IN_NONE, "INTERACTION|TYPE|SMALL SLIDING|SMOOTH|ADJUST|TIED|MECHANICAL CONSTRAINT|NAME", KwContactPair, 0, NULL},
    {"TIE", AT_MODEL, IN_NONE, "NAME|POSITION TOLERANCE|ADJUST|CYCLIC SYMMETRY|MULTISTAGE|FLUID PERIODIC|FLUID CYCLIC", KwTie, 0, NULL},
    {"PARAMETER", AT_MODEL, IN_NONE, "", KwParameter, 0, NULL},
    {"STEP", AT_MODEL | AT_BETWEEN, IN_NONE, "NAME|INC|NLGEOM|AMPLITUDE|EXTRAPOLATION", KwStep, 0, NULL},
    {"END STEP", AT_STEP, IN_NONE, "", KwEndStep, 0, NULL},
    {"COUPLED TEMPERATURE-DISPLACEMENT", AT_STEP, IN_NONE, "STEADY STATE|DELTMX|DIRECT", KwCoupled, 0, NULL},
    {"STATIC", AT_STEP, IN_NONE, "DIRECT|RIKS", KwStatic, 0, NULL},
    {"HEAT TRANSFER", AT_STEP, IN_NONE, "STEADY STATE|DELTMX|DIRECT|END|FREQUENCY|MODAL DYNAMIC", KwHeatTransfer, 0, NULL},
    {"TEMPERATURE", AT_STEP, IN_NONE, "AMPLITUDE|OP|FILE|BSTEP|BINC|ESTEP|EINC|INTERPOLATE", KwTemperature, TSL_LOAD_BOUNDARY, LineTemperature},
    {"SOILS", AT_STEP, IN_NONE, NULL, KwSoils, 0, NULL},
    {"PERMEABILITY", AT_MODEL, IN_MATERIAL, NULL, KwIgnored, IGNORED_PORE_FLUID, NULL},
    {"POROUS BULK MODULI", AT_MODEL, IN_MATERIAL, NULL, KwIgnored, IGNORED_PORE_FLUID, NULL},
    {"DYNAMIC TEMPERATURE-DISPLACEMENT", AT_STEP, IN_NONE, "EXPLICIT|DIRECT USER CONTROL|ELEMENT BY ELEMENT|SCALE FACTOR", KwDynamic, 0, NULL},
    {"FIXED MASS SCALING", AT_STEP, IN_NONE, "FACTOR|DT|ELSET|TYPE", KwMassScaling, 0, NULL},
    {"BULK VISCOSITY", AT_STEP, IN_NONE, "", KwBulkViscosity, 0, NULL},
    {"VARIABLE MASS SCALING", AT_STEP, IN_NONE, "DT|ELSET|FREQUENCY|TYPE", KwMassScaling, 1, NULL},
    {"BOUNDARY", AT_BOTH, IN_NONE, LOAD_PARAMS "|FIXED|TYPE", KwLoad, TSL_LOAD_BOUNDARY, LineBoundary},
    {"CLOAD", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_CLOAD, LineConcentrated},
    {"CFLUX", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_CFLUX, LineConcentrated},
    {"DLOAD", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_DLOAD, LineDload},
    {"DSLOAD", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_DLOAD, LineDsload},
    {"DFLUX", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_DFLUX, LineDflux},
    {"DSFLUX", AT_STEP, IN_NONE, LOAD_PARAMS, KwLoad, TSL_LOAD_DFLUX, LineDsflux},
    {"FILM", AT_STEP, IN_NONE, LOAD_PARAMS "|FILM AMPLITUDE", KwLoad, TSL_LOAD_FILM, LineFilm},
    {"SFILM", AT_STEP, IN_NONE, LOAD_PARAMS "|FILM AMPLITUDE", KwLoad, TSL_LOAD_FILM, LineFilm},
    {"RADIATE", AT_STEP, IN_NONE, LOAD_PARAMS "|RADIATION AMPLITUDE", KwLoad, TSL_LOAD_RADIATE, LineRadiate},
    {"SRADIATE", AT_STEP, IN_NONE, LOAD_PARAMS "|RADIATION AMPLITUDE", KwLoad, TSL_LOAD_RADIATE, LineRadiate},
    {"OUTPUT", AT_BOTH, IN_NONE, "FIELD|HISTORY|FREQUENCY|NUMBER INTERVAL|TIME INTERVAL|VARIABLE", KwOutput, 0, NULL},
    {"NODE OUTPUT", AT_STEP, IN_NONE, "NSET|FREQUENCY", KwOutputRequest, OUT_NODE, NULL},
    {"NODE FILE", AT_STEP, IN_NONE, "NSET|FREQUENCY", KwOutputRequest, OUT_NODE, NULL},
    {"ELEMENT OUTPUT", AT_STEP, IN_NONE, "ELSET|FREQUENCY", KwOutputRequest, 0, NULL},
    {"EL FILE", AT_STEP, IN_NONE, "ELSET|FREQUENCY", KwOutputRequest, 0, NULL},
    {"NODE PRINT", AT_STEP, IN_NONE, "NSET|FREQUENCY|TOTALS", KwOutputRequest, OUT_NODE | OUT_PRINT, NULL},
    {"EL PRINT", AT_STEP, IN_NONE, "ELSET|FREQUENCY|TOTALS", KwOutputRequest, OUT_PRINT, NULL},
    /* ignored (a warning names them); placed as the dialect places them, so a misplaced one still tells */
    {"PREPRINT", AT_MODEL, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"FILE FORMAT", AT_BOTH, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"MONITOR", AT_STEP, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"RESTART", AT_BOTH, IN_NONE, NULL, KwRestart, 0, NULL},
    {"POST OUTPUT", AT_MODEL, IN_NONE, NULL, KwPostOutput, 0, NULL},
    {"CONTACT PRINT", AT_STEP, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"CONTACT FILE", AT_STEP, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"ENERGY PRINT", AT_STEP, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"CONTACT CONTROLS", AT_BOTH, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"CONTACT OUTPUT", AT_STEP, IN_NONE, NULL, KwIgnored, 0, NULL},
    {"CONTROLS", AT_STEP, IN_NONE, NULL, KwControls, 0, NULL},
};

static const char *KeywordParams(const char *name)
{
  for (size_t i = 0; i < sizeof(Keywords) / sizeof(Keywords[0]); i++)
    if (!strcmp(Keywords[i].name, name)) return Keywords[i].params;
  return NULL;
}

/* Where the reader is now: inside a step, before the first one (model data) or between steps. */
static DeckPlacement DeckPosition(const Deck *d)
{
  return d->step >= 0 ? AT_STEP : (d->m->nstep == 0 ? AT_MODEL : AT_BETWEEN);
}

/* The placement column as the user reads it: what the dialect calls the keyword and where it goes. */
static const struct {
  PetscInt    placement;
  const char *kind, *belongs;
} PlacementText[] = {
    {AT_MODEL, "model data", "before the first *STEP"},
    {AT_STEP, "history data", "inside a step (*STEP ... *END STEP)"},
    {AT_BOTH, "model or history data", "before the first *STEP or inside a step"},
    {AT_MODEL | AT_BETWEEN, "the start of a step", "outside any other step"},
};

static PetscErrorCode CheckPlacement(Deck *d, const DeckKeyword *kw)
{
  DeckPlacement  at   = DeckPosition(d);
  const TslStep *s    = d->m->nstep ? &d->m->steps[at == AT_STEP ? d->step : 0] : NULL;
  const char    *kind = "", *belongs = "";
  char           here[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBeginUser;
  if (d->post_own) {
    /* after *POST OUTPUT (and the old job's deck it reads in its place) the deck holds its frames' output requests */
    USER_CHECK(kw->handler == KwOutput || kw->handler == KwOutputRequest,
               LOC_FMT "*%s in a POST OUTPUT deck: after *POST OUTPUT it holds output requests only (*OUTPUT, *NODE OUTPUT, *ELEMENT OUTPUT, "
                       "*NODE FILE, *EL FILE): the model and the steps are the old job's",
               KLOC(d), d->kw);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (kw->placement & at) PetscFunctionReturn(PETSC_SUCCESS);
  /* a restart deck (*RESTART, READ) may define new sets, surfaces and amplitudes for its own steps between the old job's
   * steps and them, as the dialect allows; the rest of the model is the old job's */
  if (at == AT_BETWEEN && d->m->restart_read_step > 0 && !d->restart_stop && (kw->handler == KwSet || kw->handler == KwSurface || kw->handler == KwAmplitude))
    PetscFunctionReturn(PETSC_SUCCESS);
  USER_CHECK(kw->handler != KwEndStep, LOC_FMT "*END STEP without *STEP", KLOC(d));
  for (size_t i = 0; i < sizeof(PlacementText) / sizeof(PlacementText[0]); i++)
    if (PlacementText[i].placement == (PetscInt)kw->placement) kind = PlacementText[i].kind, belongs = PlacementText[i].belongs;
  if (at == AT_STEP)
    PetscCall(PetscSNPrintf(here, sizeof(here), "here it is inside the step that starts at %s:%" PetscInt_FMT "; missing *END STEP?",
                            TslDeckFileName(d->m, s->loc.file), s->loc.line));
  else if (at == AT_BETWEEN && d->m->restart_read_step > 0 && !d->restart_stop)
    PetscCall(PetscSNPrintf(here, sizeof(here), "a restart deck defines new sets, surfaces and amplitudes only: the rest of the model is the old job's"));
  else if (at == AT_BETWEEN)
    PetscCall(PetscSNPrintf(here, sizeof(here), "here it comes after the first step, which starts at %s:%" PetscInt_FMT,
                            TslDeckFileName(d->m, s->loc.file), s->loc.line));
  else
    PetscCall(PetscSNPrintf(here, sizeof(here), "here it comes before the first *STEP"));
  USER_ERR(LOC_FMT "*%s is %s: it belongs %s (%s)", KLOC(d), d->kw, kind, belongs, here);
}

static PetscErrorCode DeckKeywordLine(Deck *d)
{
  const DeckKeyword *kw = NULL;

  PetscFunctionBeginUser;
  for (size_t i = 0; i < sizeof(Keywords) / sizeof(Keywords[0]); i++)
    if (!strcmp(Keywords[i].name, d->kw)) kw = &Keywords[i];
  USER_CHECK(kw, LOC_FMT "unsupported keyword *%s", KLOC(d), d->kw);
  if (d->post_depth && d->depth <= d->post_depth) d->post_own = PETSC_TRUE; /* back in the POST OUTPUT deck, after the old one */
  PetscCall(CheckPlacement(d, kw));
  /* what a part, an assembly and an instance may hold here (comments aside) */
  if (d->part >= 0 && kw->handler != KwIgnored)
    USER_CHECK(kw->handler == KwNode || kw->handler == KwElement || kw->handler == KwSet || kw->handler == KwSurface ||
                   kw->handler == KwSolidSection || kw->handler == KwShellSection || kw->handler == KwNodalThickness || kw->handler == KwEndPart,
               LOC_FMT "*%s inside *PART %s: a part holds nodes, elements, sets, surfaces, sections and nodal thicknesses here (missing *END PART?)",
               KLOC(d), d->kw, d->parts[d->part].name);
  if (d->instance >= 0)
    USER_CHECK(kw->handler == KwEndInstance, LOC_FMT "*%s inside *INSTANCE %s: an instance holds its placement only here (missing *END INSTANCE?)",
               KLOC(d), d->kw, d->inst[d->instance].name);
  else if (d->assembly && kw->handler != KwIgnored)
    USER_CHECK(kw->handler == KwInstance || kw->handler == KwSet || kw->handler == KwSurface || kw->handler == KwEndAssembly ||
                   kw->handler == KwNode || kw->handler == KwElement,
               LOC_FMT "*%s inside the *ASSEMBLY: an assembly holds instances, sets and surfaces here (missing *END ASSEMBLY?)", KLOC(d), d->kw);
  if (kw->block != IN_MATERIAL && kw->handler != KwIgnored) d->material = -1;
  if (kw->block != IN_INTERACTION && kw->handler != KwIgnored) d->interaction = -1;
  USER_CHECK(kw->block != IN_MATERIAL || d->material >= 0, LOC_FMT "*%s must follow *MATERIAL (material properties outside a material)", KLOC(d),
             d->kw);
  USER_CHECK(kw->block != IN_INTERACTION || d->interaction >= 0,
             LOC_FMT "*%s must follow *SURFACE INTERACTION (interface properties outside a surface interaction)", KLOC(d), d->kw);
  if (kw->params)
    for (PetscInt i = 0; i < d->nparam; i++) {
      /* An unknown parameter is ignored with a warning, unless ignoring it would change the model: data
       * from elsewhere (INPUT=, USER subroutines), field-variable dependence, cylindrical or spherical node
       * coordinates, absolute amplitude values, a perturbation step, a composite section, friction laws beyond
       * constant Coulomb (a shear limit, decay, anisotropy), CalculiX's TIME DELAY (shifts a load's amplitude) and
       * SUBMODEL. Those are errors (found by mutating decks, and TIME DELAY by CalculiX's test deck beamdelay.inp:
       * each had run a different model with a warning only). */
      static const struct {
        const char *key, *harmless; /* the value that is the default, so harmless to ignore, or NULL */
      } Meaningful[] = {
          {"USER", NULL},      {"INPUT", NULL},  {"DEPENDENCIES", "0"},       {"SYSTEM", "R"},       {"VALUE", "RELATIVE"}, {"PERTURBATION", NULL},
          {"COMPOSITE", NULL}, {"TAUMAX", NULL}, {"EXPONENTIAL DECAY", NULL}, {"ANISOTROPIC", NULL}, {"TIME DELAY", NULL},  {"SUBMODEL", NULL},
          {"RADIATION TIME DELAY", NULL},
          {"ENVNODE", NULL},
      };
      if (ParamKnown(kw->params, d->pkey[i])) continue;
      for (size_t k = 0; k < sizeof(Meaningful) / sizeof(Meaningful[0]); k++) {
        char  v[32] = "";
        char *nv    = v;
        if (strcmp(d->pkey[i], Meaningful[k].key)) continue;
        if (d->pval[i]) (void)PetscStrncpy(v, d->pval[i], sizeof(v)), nv = Normalize(v);
        USER_CHECK(Meaningful[k].harmless && !strcmp(nv, Meaningful[k].harmless),
                   LOC_FMT "*%s, %s%s%s is not supported: ignoring it would change the model", KLOC(d), d->kw, d->pkey[i], d->pval[i] ? "=" : "",
                   d->pval[i] ? d->pval[i] : "");
      }
      PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "warning: parameter %s of *%s is ignored\n", KLOC(d), d->pkey[i], d->kw));
    }
  PetscCall(kw->handler(d, kw));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DeckParse(Deck *d, const char *path)
{
  const char *s;
  PetscBool   got;

  PetscFunctionBeginUser;
  PetscCall(DeckOpen(d, path, PETSC_FALSE));
  for (;;) {
    PetscCall(RawNext(d, &s, &got));
    if (!got) break;
    if (!IsKeywordLine(s)) {
      if (d->kw) USER_ERR(LOC_FMT "data line not expected here (after *%s)", DLOC(d), d->kw);
      USER_ERR(LOC_FMT "data line before the first keyword", DLOC(d));
    }
    PetscCall(KeywordLine(d, s));
    PetscCall(DeckKeywordLine(d));
    d->nkeyword++;
  }
  USER_CHECK(d->nkeyword > 0, "%s:0: the deck is empty (no keyword lines)", path);
  if (d->part >= 0) USER_ERR(LOC_FMT "missing *END PART: the deck ends inside this part", TSL_LOC_ARGS(d->m, d->parts[d->part].loc));
  if (d->assembly) USER_ERR(LOC_FMT "missing *END ASSEMBLY: the deck ends inside this assembly", TSL_LOC_ARGS(d->m, d->assembly_loc));
  for (PetscInt i = 0; i < d->npart; i++) /* an uninstanced part is not in the model, but its nodes were read into it */
    if (d->parts[i].first < 0)
      USER_ERR(LOC_FMT "part %s is never instanced (an *INSTANCE, PART=%s in the *ASSEMBLY places it)", TSL_LOC_ARGS(d->m, d->parts[i].loc),
               d->parts[i].name, d->parts[i].name);
  if (d->step >= 0) {
    TslLoc l = d->m->steps[d->step].loc;
    USER_ERR(LOC_FMT "missing *END STEP: the deck ends inside this step", TSL_LOC_ARGS(d->m, l));
  }
  if (d->restart_stop)
    USER_ERR(LOC_FMT "*RESTART, READ, STEP=%" PetscInt_FMT ": the old job's deck has %" PetscInt_FMT " steps", TSL_LOC_ARGS(d->m, d->m->restart_read_loc),
             d->restart_stop, d->m->nstep);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The model-data *BOUNDARY conditions become the first step's first loads, so that they apply from
 * that step on and later steps modify them like any other (OP=MOD), with nothing new downstream.
 * A *BOUNDARY, OP=NEW in the first step removes them, as in Abaqus: then they are dropped here. */
static PetscErrorCode DeckModelLoads(Deck *d)
{
  TslStep *s;

  PetscFunctionBeginUser;
  if (!d->nmload || !d->m->nstep) PetscFunctionReturn(PETSC_SUCCESS); /* no step: TslModelCheck says so */
  s = &d->m->steps[0];
  for (PetscInt i = 0; i < s->nload; i++)
    if (s->loads[i].kind == TSL_LOAD_BOUNDARY && s->loads[i].op_new) {
      PetscCall(PetscInfo(NULL, "*BOUNDARY, OP=NEW at %s:%" PetscInt_FMT " removes the %" PetscInt_FMT " model-data boundary condition(s)\n",
                          TslDeckFileName(d->m, s->loads[i].loc.file), s->loads[i].loc.line, d->nmload));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  for (PetscInt i = 0; i < d->nmload; i++) PetscCall(TslDeckGrow(&s->loads, sizeof(TslLoad), s->nload + i));
  if (s->nload) memmove(s->loads + d->nmload, s->loads, (size_t)s->nload * sizeof(TslLoad));
  memcpy(s->loads, d->mload, (size_t)d->nmload * sizeof(TslLoad));
  s->nload += d->nmload;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Duplicate node ids, reported at the later definition (nodes carry no location in the model). */
static PetscErrorCode DeckCheckDuplicateNodes(Deck *d)
{
  TslModel *m = d->m;
  PetscInt *id, *pos;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(m->nnode, &id));
  PetscCall(PetscMalloc1(m->nnode, &pos));
  for (PetscInt i = 0; i < m->nnode; i++) id[i] = m->node_id[i], pos[i] = i;
  PetscCall(PetscSortIntWithArray(m->nnode, id, pos));
  for (PetscInt i = 1; i < m->nnode; i++) {
    if (id[i] == id[i - 1]) {
      PetscInt a = PetscMin(pos[i], pos[i - 1]), b = PetscMax(pos[i], pos[i - 1]), dup = id[i];
      TslLoc   la = {d->node_line[2 * a], d->node_line[2 * a + 1]}, lb = {d->node_line[2 * b], d->node_line[2 * b + 1]};
      PetscCall(PetscFree(id));
      PetscCall(PetscFree(pos));
      USER_ERR(LOC_FMT "duplicate node id %" PetscInt_FMT " (first defined at %s:%" PetscInt_FMT ")", TSL_LOC_ARGS(m, lb), dup,
               TslDeckFileName(m, la.file), la.line);
    }
  }
  PetscCall(PetscFree(id));
  PetscCall(PetscFree(pos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A model whose steps are all *HEAT TRANSFER has the temperature alone: every element becomes the heat-transfer type
 * of its interpolation and measure (TslElementTypeHeatCounterpart: C3D8T, CalculiX's C3D8 and Abaqus's DC3D8 alike),
 * so that the layout has one unknown per node. *HEAT TRANSFER steps are not mixed with mechanical ones (the coupled
 * types' displacements would have to be held through them; Abaqus refuses its DC types in stress steps); a DC type
 * in a model with other steps is an error at its element. */
static PetscErrorCode DeckHeatTransferModel(Deck *d)
{
  TslModel *m     = d->m;
  PetscInt  nheat = 0, other = -1, heat = -1;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nstep; i++) {
    if (m->steps[i].heat) nheat++, heat = heat < 0 ? i : heat;
    else if (m->steps[i].coupled && other < 0) other = i;
  }
  if (nheat && other >= 0) {
    const TslStep *h = &m->steps[heat], *o = &m->steps[other];
    USER_ERR(LOC_FMT "step %s: *HEAT TRANSFER steps cannot be mixed with the mechanical step %s at %s:%" PetscInt_FMT
                     " (a heat-transfer model has the temperature alone; run the heat transfer as *COUPLED TEMPERATURE-DISPLACEMENT)",
             TSL_LOC_ARGS(m, h->heat_loc), h->name, o->name, TSL_LOC_ARGS(m, o->loc));
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(m->elem_type[e]);
    const TslLoc          l = {m->elem_line[2 * e], m->elem_line[2 * e + 1]};
    PetscInt              h;
    if (!nheat) {
      USER_CHECK(!TslElementTypeHeatOnly(t) || other < 0,
                 LOC_FMT "element %" PetscInt_FMT " is of the heat-transfer type %s, which runs in *HEAT TRANSFER steps only: step %s at %s:%" PetscInt_FMT
                         " is a mechanical one (mechanical steps take the coupled temperature-displacement types: CPE4T, C3D8T, ...)",
                 TSL_LOC_ARGS(m, l), m->elem_id[e], t->name, other >= 0 ? m->steps[other].name : "", TSL_LOC_ARGS(m, m->steps[PetscMax(other, 0)].loc));
      continue;
    }
    if (TslElementTypeHeatOnly(t)) continue;
    h = TslElementTypeHeatCounterpart(t);
    USER_CHECK(h >= 0,
               LOC_FMT "element %" PetscInt_FMT " of type %s (%s) has no heat-transfer counterpart, and every step is *HEAT TRANSFER (docs/elements.md, "
                       "\"Heat transfer\")",
               TSL_LOC_ARGS(m, l), m->elem_id[e], t->name, TslElementTypeKinematicsName(t));
    if (!d->type_note) PetscCall(PetscCalloc2(TslElementTypeCount(), &d->type_note, TslElementTypeCount(), &d->type_mech));
    if (!d->type_note[m->elem_type[e]].line) d->type_note[m->elem_type[e]] = l;
    m->elem_type[e] = h;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The types read under another name, noted once each: CalculiX's mechanical names read as the coupled types in
 * coupled steps, and any type read as its heat-transfer counterpart in a heat-transfer model. */
static PetscErrorCode DeckTypeNotes(Deck *d)
{
  PetscBool heat = d->m->nstep && d->m->steps[0].heat;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; d->type_note && i < TslElementTypeCount(); i++) {
    const TslElementType *t = TslElementTypeGet(i);
    const int             n = (int)strlen(t->name) - (d->type_mech[i] ? 1 : 0); /* the name the deck gave */
    if (!d->type_note[i].line) continue;
    if (heat)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, LOC_FMT "note: element type %.*s read as %s (every step is *HEAT TRANSFER: the temperature alone)\n",
                            TSL_LOC_ARGS(d->m, d->type_note[i]), n, t->name, TslElementTypeGet(TslElementTypeHeatCounterpart(t))->name));
    else
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            LOC_FMT "note: element type %.*s read as %s (the steps here are coupled temperature-displacement ones; CalculiX "
                                    "gives its mechanical elements a temperature in such a step)\n",
                            TSL_LOC_ARGS(d->m, d->type_note[i]), n, t->name, t->name));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DeckFree(Deck *d)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(d->type_note, d->type_mech));
  for (PetscInt i = 0; i < d->ntext; i++) PetscCall(PetscFree(d->texts[i]));
  PetscCall(PetscFree(d->texts));
  PetscCall(PetscFree(d->buf));
  PetscCall(PetscFree(d->kwbuf));
  PetscCall(PetscFree(d->field));
  PetscCall(PetscFree(d->node_line));
  PetscCall(PetscFree(d->mload));
  for (PetscInt i = 0; i < d->npart; i++) PetscCall(PetscFree(d->parts[i].xyz));
  PetscCall(PetscFree(d->parts));
  PetscCall(PetscFree(d->inst));
  PetscCall(PetscFree(d->parameters));
  PetscCall(PetscFree(d->subst));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslDeckRead(const char *path, TslModel **model)
{
  PetscFunctionBeginUser;
  PetscCall(TslDeckReadFlat(path, model, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslDeckReadFlat(const char *path, TslModel **model, char **flat)
{
  Deck           d;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  *model = NULL;
  if (flat) *flat = NULL;
  PetscCall(PetscMemzero(&d, sizeof(d)));
  d.record              = (PetscBool)(flat != NULL);
  d.step                = -1;
  d.material            = -1;
  d.interaction         = -1;
  d.out_frequency_model = 1;
  d.part                = -1;
  d.instance            = -1;
  PetscCall(TslModelCreate(&d.m));
  /* On a user error the partial model and the reader's buffers are freed before the error goes up. */
  ierr = DeckParse(&d, path);
  if (!ierr && !d.m->dim && d.m->nelem) d.m->dim = 3; /* links alone: a 3D model */
  if (!ierr) ierr = DeckModelLoads(&d);
  if (!ierr) ierr = DeckCheckDuplicateNodes(&d);
  if (!ierr) ierr = TslDeckExpandShells(d.m);
  if (!ierr) ierr = DeckHeatTransferModel(&d);
  if (!ierr) ierr = DeckTypeNotes(&d);
  if (!ierr) ierr = TslModelCheck(d.m);
  PetscCall(DeckFree(&d));
  if (ierr) PetscCall(TslModelDestroy(&d.m));
  if (ierr) PetscCall(PetscFree(d.flat));
  PetscCall(ierr);
  *model = d.m;
  if (flat) *flat = d.flat;
  PetscFunctionReturn(PETSC_SUCCESS);
}
