#include "io/vtu_format.hpp"

#include <bit>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace pdq::vtu {
namespace {

static_assert(std::endian::native == std::endian::little, "the VTU writer assumes little-endian");

const char* kHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"%TYPE%\" version=\"1.0\" byte_order=\"LittleEndian\" "
    "header_type=\"UInt64\">\n";

std::string header(const std::string& type) {
  std::string h = kHeader;
  h.replace(h.find("%TYPE%"), 6, type);
  return h;
}

// XML attribute values: names come from model schemas, so escape what XML requires.
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The appended block: each array is a UInt64 byte count then its raw bytes; an array's
// `offset` is where its count starts, relative to the block's first byte. Offsets are
// laid out first so the arrays then stream straight from memory to the file.
class Appended {
 public:
  template <class T>
  std::uint64_t add(const std::vector<T>& v) {
    const std::uint64_t offset = size_;
    parts_.push_back({reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)});
    size_ += sizeof(std::uint64_t) + parts_.back().second;
    return offset;
  }
  void write(std::ostream& os) const {
    for (const auto& [data, bytes] : parts_) {
      const std::uint64_t n = bytes;
      os.write(reinterpret_cast<const char*>(&n), sizeof n);
      if (n) os.write(data, static_cast<std::streamsize>(n));
    }
  }

 private:
  std::vector<std::pair<const char*, std::size_t>> parts_;
  std::uint64_t size_ = 0;
};

void arrayTag(std::ostream& os, const char* indent, const char* type, const std::string& name,
              int components, std::uint64_t offset) {
  os << indent << "<DataArray type=\"" << type << "\"";
  if (!name.empty()) os << " Name=\"" << escape(name) << "\"";
  os << " NumberOfComponents=\"" << components << "\" format=\"appended\" offset=\"" << offset
     << "\"/>\n";
}

void dataArrays(std::ostream& os, const std::vector<Array>& arrays, Appended& block) {
  for (const Array& a : arrays) {
    const std::uint64_t off = a.integer ? block.add(a.i64) : block.add(a.f64);
    arrayTag(os, "        ", a.integer ? "Int64" : "Float64", a.name, a.components, off);
  }
}

}  // namespace

void Piece::addCell(CellType t, std::initializer_list<std::int64_t> nodes) {
  connectivity.insert(connectivity.end(), nodes);
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  types.push_back(t);
}

void writePiece(std::ostream& out, const Piece& p) {
  Appended block;
  std::ostringstream os;
  os << header("UnstructuredGrid") << "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << p.nPoints() << "\" NumberOfCells=\"" << p.nCells()
     << "\">\n";
  os << "      <PointData>\n";
  dataArrays(os, p.pointData, block);
  os << "      </PointData>\n      <CellData>\n";
  dataArrays(os, p.cellData, block);
  os << "      </CellData>\n      <Points>\n";
  arrayTag(os, "        ", "Float64", "Points", 3, block.add(p.points));
  os << "      </Points>\n      <Cells>\n";
  arrayTag(os, "        ", "Int64", "connectivity", 1, block.add(p.connectivity));
  arrayTag(os, "        ", "Int64", "offsets", 1, block.add(p.offsets));
  arrayTag(os, "        ", "UInt8", "types", 1, block.add(p.types));
  os << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
     << "  <AppendedData encoding=\"raw\">\n   _";
  out << os.str();
  block.write(out);
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

std::string encodeParallel(const Piece& layout, const std::vector<std::string>& pieceFiles) {
  std::ostringstream os;
  os << header("PUnstructuredGrid") << "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  auto arrays = [&](const char* tag, const std::vector<Array>& v) {
    os << "    <" << tag << ">\n";
    for (const Array& a : v)
      os << "      <PDataArray type=\"" << (a.integer ? "Int64" : "Float64") << "\" Name=\""
         << escape(a.name) << "\" NumberOfComponents=\"" << a.components << "\"/>\n";
    os << "    </" << tag << ">\n";
  };
  arrays("PPointData", layout.pointData);
  arrays("PCellData", layout.cellData);
  os << "    <PPoints>\n      <PDataArray type=\"Float64\" Name=\"Points\" "
        "NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const std::string& f : pieceFiles) os << "    <Piece Source=\"" << escape(f) << "\"/>\n";
  os << "  </PUnstructuredGrid>\n</VTKFile>\n";
  return os.str();
}

std::string encodeSeries(const std::vector<SeriesEntry>& entries) {
  std::ostringstream os;
  os << header("Collection") << "  <Collection>\n";
  os << std::setprecision(17);
  for (const SeriesEntry& e : entries)
    os << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\""
       << escape(e.file) << "\"/>\n";
  os << "  </Collection>\n</VTKFile>\n";
  return os.str();
}

}  // namespace pdq::vtu
