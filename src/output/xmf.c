/* The XDMF 3 text describing <job>.h5 as a temporal collection, one Uniform grid per frame. The mesh
 * datasets are referenced again by each grid (not xi:included) so that every grid stands alone; the
 * text is small and the data is shared in the .h5 anyway. */
#include "output_impl.h"
#include <errno.h>

/* ParaView's XDMF reader wants 3 components for a Vector and 9 for a full Tensor. Six components are
 * written as a plain Matrix, not Tensor6: our stresses and strains are in the dialect's order (11, 22,
 * 33, 12, 13, 23), XDMF's Tensor6 is (xx, xy, xz, yy, yz, zz), and a reader would label them wrongly. */
static const char *AttributeType(PetscInt ncomp)
{
  switch (ncomp) {
  case 1:
    return "Scalar";
  case 3:
    return "Vector";
  case 9:
    return "Tensor";
  default:
    return "Matrix";
  }
}

/* Text in XML: the job name (from the deck's file name) may hold any of & < > " '. */
static void PutXml(FILE *fp, const char *text)
{
  for (const char *c = text; *c; c++) {
    switch (*c) {
    case '&':
      fputs("&amp;", fp);
      break;
    case '<':
      fputs("&lt;", fp);
      break;
    case '>':
      fputs("&gt;", fp);
      break;
    case '"':
      fputs("&quot;", fp);
      break;
    case '\'':
      fputs("&apos;", fp);
      break;
    default:
      fputc(*c, fp);
    }
  }
}

/* XDMF's cell types (XdmfTopologyType: the ids of its Mixed records, the names of a single-type topology) with a
 * fixed node count. */
static const struct {
  PetscInt    id, nodes;
  const char *name;
} XdmfTypes[] = {
    {1, 1, "Polyvertex"},     {2, 2, "Polyline"},         {4, 3, "Triangle"},   {5, 4, "Quadrilateral"}, {6, 4, "Tetrahedron"},
    {7, 5, "Pyramid"},        {8, 6, "Wedge"},            {9, 8, "Hexahedron"}, {34, 3, "Edge_3"},       {36, 6, "Triangle_6"},
    {37, 8, "Quadrilateral_8"}, {38, 10, "Tetrahedron_10"}, {39, 13, "Pyramid_13"}, {40, 15, "Wedge_15"}, {48, 20, "Hexahedron_20"},
};

const char *TslXdmfTopologyName(PetscInt xdmf_type, PetscInt *nodes)
{
  for (size_t i = 0; i < sizeof(XdmfTypes) / sizeof(XdmfTypes[0]); i++)
    if (XdmfTypes[i].id == xdmf_type) {
      *nodes = XdmfTypes[i].nodes;
      return XdmfTypes[i].name;
    }
  *nodes = 0;
  return NULL;
}

/* A mesh of one cell type gets that type's own topology (Hexahedron_20, ...: every reader knows those, meshio
 * included) on /mesh/connectivity; a mixed one the Mixed records of /mesh/topology (docs/output.md says which
 * readers take which). */
static void WriteMesh(FILE *fp, TslOutput out)
{
  if (out->cell_name) {
    fprintf(fp, "        <Topology TopologyType=\"%s\" NumberOfElements=\"%" PetscInt_FMT "\" NodesPerElement=\"%" PetscInt_FMT "\">\n", out->cell_name,
            out->nelem_global, out->cell_nodes);
    fprintf(fp, "          <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">",
            out->nelem_global, out->cell_nodes);
    PutXml(fp, out->h5_base);
    fprintf(fp, ":/mesh/connectivity</DataItem>\n");
  } else {
    fprintf(fp, "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"%" PetscInt_FMT "\">\n", out->nelem_global);
    fprintf(fp, "          <DataItem Dimensions=\"%lld\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">", (long long)out->topo_len);
    PutXml(fp, out->h5_base);
    fprintf(fp, ":/mesh/topology</DataItem>\n");
  }
  fprintf(fp, "        </Topology>\n");
  fprintf(fp, "        <Geometry GeometryType=\"XYZ\">\n");
  fprintf(fp, "          <DataItem Dimensions=\"%" PetscInt_FMT " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">", out->nnode_global);
  PutXml(fp, out->h5_base);
  fprintf(fp, ":/mesh/coordinates</DataItem>\n");
  fprintf(fp, "        </Geometry>\n");
}

PetscErrorCode TslOutputWriteXmf(TslOutput out, const char *path, int *err)
{
  FILE *fp;

  PetscFunctionBeginUser;
  *err = 0;
  fp   = fopen(path, "w");
  if (!fp) {
    *err = errno;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* Field names were checked for XML-special characters when they were given; the job name is escaped. */
  fprintf(fp, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n");
  fprintf(fp, "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n  <Domain>\n");
  fprintf(fp, "    <Grid Name=\"");
  PutXml(fp, out->job);
  fprintf(fp, "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (PetscInt i = 0; i < out->nframe; i++) {
    const TslOutputFrameInfo *f = &out->frames[i];
    if (out->in_frame && i == out->nframe - 1) break; /* the open frame is not complete yet */
    fprintf(fp, "      <Grid Name=\"frame%06d\" GridType=\"Uniform\">\n", (int)(i + 1));
    fprintf(fp, "        <Time Value=\"%.17g\"/>\n", (double)f->time);
    fprintf(fp, "        <Information Name=\"step\" Value=\"%" PetscInt_FMT "\"/>\n", f->step);
    fprintf(fp, "        <Information Name=\"increment\" Value=\"%" PetscInt_FMT "\"/>\n", f->increment);
    WriteMesh(fp, out);
    for (PetscInt j = 0; j < f->nfield; j++) {
      const TslOutputFieldInfo *a = &f->fields[j];
      fprintf(fp, "        <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"%s\">\n", a->name, AttributeType(a->ncomp),
              a->on_cells ? "Cell" : "Node");
      fprintf(fp, "          <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">",
              a->on_cells ? out->nelem_global : out->nnode_global, a->ncomp);
      PutXml(fp, out->h5_base);
      fprintf(fp, ":/frames/%06d/%s</DataItem>\n", (int)(i + 1), a->name);
      fprintf(fp, "        </Attribute>\n");
    }
    fprintf(fp, "      </Grid>\n");
  }
  fprintf(fp, "    </Grid>\n  </Domain>\n</Xdmf>\n");
  if (ferror(fp)) *err = errno ? errno : EIO;
  if (fclose(fp) && !*err) *err = errno ? errno : EIO;
  PetscFunctionReturn(PETSC_SUCCESS);
}
