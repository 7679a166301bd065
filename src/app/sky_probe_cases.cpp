// Reading the sky-probe CSV (sky_probe_cases.h).
#include "app/sky_probe_cases.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "scene/toml_error.h"
#include "util/file_util.h"

namespace planet {

namespace {

std::string trim(std::string_view s) {
    const std::size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string_view::npos) return {};
    const std::size_t b = s.find_last_not_of(" \t\r");
    return std::string(s.substr(a, b - a + 1));
}

std::vector<std::string> splitFields(std::string_view line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                 : comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

struct Range {
    double lo, hi;
    const char* unit;
};
constexpr Range kRanges[4] = {{0.0, 1e9, "m"}, {0.0, 180.0, "deg"}, {0.0, 180.0, "deg"}, {-360.0, 360.0, "deg"}};

// One data row, checked column by column.
ProbeRow parseRow(const std::vector<std::string>& fields, const std::string& source, int lineNo) {
    ProbeRow row{};
    double* values[4] = {&row.altitudeM, &row.sunZenithDeg, &row.viewZenithDeg, &row.viewAzimuthDeg};
    for (int c = 0; c < 4; ++c) {
        const std::string& f = fields[static_cast<std::size_t>(c)];
        double v = 0.0;
        const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
        if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
            throw InputError(source, lineNo, kProbeInputColumns[c], "'" + f + "' is not a number");
        const Range& r = kRanges[c];
        if (!(v >= r.lo && v <= r.hi)) {
            char message[160];
            std::snprintf(message, sizeof message, "value %s is out of range [%g, %g] %s", f.c_str(), r.lo, r.hi,
                          r.unit);
            throw InputError(source, lineNo, kProbeInputColumns[c], message);
        }
        *values[c] = v;
        row.text[c] = f;
    }
    return row;
}

}  // namespace

namespace {

// Calls row(fields, lineNo) for each data line of a CSV whose header is `columns`
// and whose lines have that many fields.
template <class RowFn>
void forEachRow(std::string_view csvText, const std::string& sourceName, const std::vector<std::string>& columns,
                RowFn row) {
    std::string expectedHeader;
    for (const std::string& c : columns) expectedHeader += (expectedHeader.empty() ? "" : ",") + c;
    bool sawHeader = false;
    int lineNo = 0;
    for (std::size_t start = 0; start < csvText.size();) {
        const std::size_t newline = csvText.find('\n', start);
        const std::size_t end = newline == std::string_view::npos ? csvText.size() : newline;
        const std::string_view line = csvText.substr(start, end - start);
        start = end + 1;
        ++lineNo;
        if (trim(line).empty()) continue;
        const std::vector<std::string> fields = splitFields(line);
        if (!sawHeader) {
            std::string header;
            for (const std::string& f : fields) header += (header.empty() ? "" : ",") + f;
            if (header != expectedHeader)
                throw InputError(sourceName, lineNo, "",
                                 "expected the header '" + expectedHeader + "', found '" + trim(line) + "'");
            sawHeader = true;
            continue;
        }
        if (fields.size() != columns.size())
            throw InputError(sourceName, lineNo, "",
                             "expected " + std::to_string(columns.size()) + " columns (" + expectedHeader +
                                 "), found " + std::to_string(fields.size()));
        row(fields, lineNo);
    }
    if (!sawHeader)
        throw InputError(sourceName, 0, "", "empty file: expected the header '" + expectedHeader + "'");
}

std::vector<std::string> inputColumns() { return {std::begin(kProbeInputColumns), std::end(kProbeInputColumns)}; }

}  // namespace

std::vector<ProbeRow> parseProbeCases(std::string_view csvText, const std::string& sourceName) {
    std::vector<ProbeRow> rows;
    forEachRow(csvText, sourceName, inputColumns(),
               [&](const std::vector<std::string>& fields, int lineNo) {
                   rows.push_back(parseRow(fields, sourceName, lineNo));
               });
    return rows;
}

std::vector<ProbeResultRow> parseProbeResults(std::string_view csvText, const std::string& sourceName) {
    std::vector<std::string> columns = inputColumns();
    for (const char* c : kProbeOutputColumns) columns.push_back(c);
    std::vector<ProbeResultRow> rows;
    forEachRow(csvText, sourceName, columns, [&](const std::vector<std::string>& fields, int lineNo) {
        ProbeResultRow row{parseRow(fields, sourceName, lineNo), {}, {}};
        for (int c = 0; c < 6; ++c) {
            const std::string& f = fields[static_cast<std::size_t>(4 + c)];
            double v = 0.0;
            const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
            // Finite, not necessarily >= 0: through clouds the radiance is a difference of two
            // lookups (Bruneton's) and can come out a rounding below 0 in the command's own output.
            if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
                throw InputError(sourceName, lineNo, kProbeOutputColumns[c], "'" + f + "' is not a finite number");
            (c < 3 ? row.radiance : row.transmittance)[c % 3] = v;
        }
        rows.push_back(row);
    });
    return rows;
}

std::vector<ProbeResultRow> readProbeResults(const std::filesystem::path& file) {
    return parseProbeResults(readFile(file), file.string());
}

std::vector<ProbeRow> readProbeCases(const std::filesystem::path& file) {
    return parseProbeCases(readFile(file), file.string());
}

}  // namespace planet
