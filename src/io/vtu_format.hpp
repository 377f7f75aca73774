#pragma once
// VTK XML files for ParaView: unstructured-grid pieces (.vtu) with every array in one
// appended raw binary block (no base64, no compression: the fastest to write and read,
// and 8 bytes per double), the parallel header that names a step's pieces (.pvtu), and
// the time-series collection (.pvd). Pure encoding: no MPI, no file names.
#include <cstdint>
#include <initializer_list>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace pdq::vtu {

// One named point or cell array: Float64 values in f64, or Int64 values in i64 when
// `integer` (components per tuple, tuples in order).
struct Array {
  std::string name;
  int components = 1;
  bool integer = false;
  std::vector<double> f64;
  std::vector<std::int64_t> i64;
};

// VTK cell types used here.
enum CellType : std::uint8_t { Vertex = 1, Line = 3 };

struct Piece {
  std::vector<double> points;  // x, y, z per point
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;  // end of each cell in connectivity
  std::vector<std::uint8_t> types;
  std::vector<Array> pointData, cellData;

  std::size_t nPoints() const { return points.size() / 3; }
  std::size_t nCells() const { return types.size(); }
  void addCell(CellType t, std::initializer_list<std::int64_t> nodes);
};

// Streams the piece (XML header, then the arrays' bytes straight from the vectors).
void writePiece(std::ostream& out, const Piece& piece);
// The .pvtu of one step: array layout taken from `layout`, pieces by relative file name.
std::string encodeParallel(const Piece& layout, const std::vector<std::string>& pieceFiles);

struct SeriesEntry {
  double time;
  std::string file;  // relative to the .pvd
};
std::string encodeSeries(const std::vector<SeriesEntry>& entries);

}  // namespace pdq::vtu
