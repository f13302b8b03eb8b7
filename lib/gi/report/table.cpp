#include "gi/report/table.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "gi/core/atomic_file.hpp"

namespace gi {

std::string format_number(double value, int precision, Format format) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  const double magnitude = std::abs(value);
  const bool scientific =
      format == Format::Scientific || (format == Format::Auto && value != 0 && (magnitude < 1e-3 || magnitude >= 1e7));
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, scientific ? "%.*e" : "%.*f", precision, value);
  return buffer;
}

namespace {

std::string cell_text(const Cell& cell, const Column& column) {
  if (const auto* i = std::get_if<long long>(&cell.value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&cell.value)) return format_number(*d, column.precision, column.format);
  return std::get<std::string>(cell.value);
}

// Full precision for CSV: the shortest text that reads back as the same double.
std::string csv_text(const Cell& cell) {
  if (const auto* i = std::get_if<long long>(&cell.value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&cell.value)) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", *d);
    return buffer;
  }
  const std::string& s = std::get<std::string>(cell.value);
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

Table::Table(std::string title, std::vector<Column> columns) : title_(std::move(title)), columns_(std::move(columns)) {}

void Table::add_row(std::vector<Cell> cells) {
  if (cells.size() != columns_.size())
    throw std::invalid_argument("table '" + title_ + "': a row needs " + std::to_string(columns_.size()) +
                                " cells, got " + std::to_string(cells.size()));
  // A NaN or an infinity in a table is a number that went wrong, never a result: the
  // lesson stops (status 1) rather than print it and exit 0. A value that does not
  // exist is a text cell ("-") with the reason said under the table.
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (const auto* d = std::get_if<double>(&cells[c].value); d && !std::isfinite(*d))
      throw std::runtime_error("table '" + title_ + "', column '" + columns_[c].name + "': the value is " +
                               (std::isnan(*d) ? "not a number (NaN)" : "infinite") + "; it cannot be shown");
  rows_.push_back(std::move(cells));
}

TableText Table::text() const {
  TableText t{title_, {}, std::vector<std::vector<std::string>>(rows_.size()), std::vector<bool>(columns_.size(), false)};
  for (const Column& column : columns_) t.header.push_back(column.name);
  for (std::size_t r = 0; r < rows_.size(); ++r)
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      t.rows[r].push_back(cell_text(rows_[r][c], columns_[c]));
      if (!std::holds_alternative<std::string>(rows_[r][c].value)) t.numeric[c] = true;
    }
  return t;
}

std::string Table::to_string() const {
  // Text cells align left, numbers right; each column is as wide as its widest entry.
  const TableText t = text();
  std::vector<std::size_t> width(columns_.size());
  for (std::size_t c = 0; c < columns_.size(); ++c) width[c] = t.header[c].size();
  for (const auto& row : t.rows)
    for (std::size_t c = 0; c < columns_.size(); ++c) width[c] = std::max(width[c], row[c].size());
  auto pad = [](const std::string& s, std::size_t w, bool left) {
    const std::string space(w - s.size(), ' ');
    return left ? s + space : space + s;
  };
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s;
    for (std::size_t c = 0; c < cells.size(); ++c) s += (c ? "  " : "") + pad(cells[c], width[c], !t.numeric[c]);
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s + '\n';
  };
  std::ostringstream os;
  if (!title_.empty()) os << title_ << '\n';
  os << line(t.header);
  std::size_t total = 0;
  for (std::size_t c = 0; c < columns_.size(); ++c) total += width[c] + (c ? 2 : 0);
  os << std::string(total, '-') << '\n';
  for (const auto& cells : t.rows) os << line(cells);
  return os.str();
}

void Table::print(std::ostream& os) const { os << to_string() << std::flush; }

void Table::write_csv(const std::filesystem::path& file) const {
  write_atomically(file, [&](std::ostream& out) {
    for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << csv_text(Cell(columns_[c].name));
    out << '\n';
    for (const auto& row : rows_) {
      for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << csv_text(row[c]);
      out << '\n';
    }
  });
}

}  // namespace gi
