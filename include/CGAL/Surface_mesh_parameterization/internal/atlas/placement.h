// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PLACEMENT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PLACEMENT_H

// The occupancy of the atlas and the search for the first free position of a chart (the
// bitmap packer of packing.h, after xatlas's and Thekla's).
//
// The atlas is a square of `size` texels. A chart is a frame of W x H cells, its mask D (its
// own cells dilated by the gutter, raster.h); a frame origin (X, Y) puts the mask's cell
// (i, j) on the atlas texel (X + i, Y + j), 0 <= X <= size - W, 0 <= Y <= size - H. The chart
// fits where D meets no occupied texel; placing it occupies its own cells.
//
// Free windows. For every level k (2^k <= size) and every m <= max_band_level, the bit row
// V[k][m][y]: bit p set when the texels p .. p + 2^k - 1 of the rows y .. y + 2^m - 1 are all
// free (a free block of 2^k x 2^m texels at (p, y)). V[k][0] = W_k is computed along the row
// (W_k = W_{k-1} & (W_{k-1} >> 2^{k-1})), V[k][m] = V[k][m-1][y] & V[k][m-1][y + 2^{m-1}].
// Any free rectangle of at least 2^k x 2^m texels is the union of four blocks, so a rectangle
// test costs four bits whatever its size; a row of V tests 64 positions X at once.
//
// A mask is tested at a frame row Y in four steps, each a necessary condition of the next:
// 1. its bands (rectangles of set cells over at most 2^max_band_level rows: the columns common
//    to the longest runs of rows that share 7/8 of them) against the longest free run of each
//    row of V[0][m] (a band of L columns needs one at least as long in its rows);
// 2. the bands against the summaries of their levels: per row of V[k][m], bit j when the
//    texels j 2^g .. (j + 1) 2^g - 1 hold a window (2^g = size / 64 rounded up to a power of
//    2, at least 1): the groups of X where every band may start;
// 3. in those groups, the bands' four blocks, 64 positions X at once;
// 4. the mask's runs of set cells (row r, start a, length L: one window of level
//    k = floor(log2 L) at a and one at a + L - 2^k), the exact test.
// The rows Y are scanned from the top, from the lowest that every band allows (per m and L,
// the first row whose longest free run of V[0][m] reaches L, kept between searches: placing
// only shortens free runs).
//
// Placing a chart updates, per row, the words of each level that the chart's new cells can
// change (the windows that meet them and start in the free run they were in), a level only
// where the level below it changed, and the levels that no search still to come reads
// (their lifetimes, given by packing.h) not at all.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/raster.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// floor(log2(n)) for n >= 1.
inline int floor_log2(int n)
{
  int k = 0;
  while((n >> (k + 1)) != 0)
    ++k;
  return k;
}

// A run of set cells of a mask: the cells start .. start + length - 1 of the row `row`;
// `level` = floor(log2(length)), `tail` = start + length - 2^level.
struct Mask_run
{
  int row = 0, start = 0, length = 0;
  int level = 0, tail = 0;
};

// A rectangle of set cells of a mask: the rows row .. row + height - 1, with
// `row_level` = floor(log2(height)) and `last_row` = row + height - 2^row_level, and the
// columns start .. start + length - 1, with `level` and `tail` as in Mask_run.
struct Mask_band
{
  int row = 0, last_row = 0, row_level = 0;
  int start = 0, length = 0, tail = 0, level = 0;
};

// The runs and bands of a mask (views into the packer's workspace).
struct Chart_mask
{
  const Mask_run* runs = nullptr;
  int run_count = 0;
  const Mask_band* bands = nullptr;
  int band_count = 0;
};

// Appends the runs of `raster` to `runs`, sorted longest first (ties by row and start): the
// longest runs fail first.
inline void compute_mask_runs(const Raster_view& raster, std::vector<Mask_run>& runs)
{
  const std::size_t first = runs.size();
  for(int r = 0; r < raster.height; ++r)
  {
    const std::uint64_t* row = raster.row(r);
    for(int x = next_bit(row, 0, raster.width, true); x < raster.width; x = next_bit(row, x, raster.width, true))
    {
      const int end = next_bit(row, x, raster.width, false), level = floor_log2(end - x);
      runs.push_back(Mask_run{r, x, end - x, level, end - (1 << level)});
      x = end;
    }
  }
  std::sort(runs.begin() + std::ptrdiff_t(first), runs.end(), [](const Mask_run& a, const Mask_run& b) {
    return a.length != b.length ? a.length > b.length : (a.row != b.row ? a.row < b.row : a.start < b.start);
  });
}

// The longest run of each row of `raster` as [begin, end) (an empty row: begin = end = 0).
inline void longest_runs(const Raster_view& raster, std::vector<int>& begin, std::vector<int>& end)
{
  begin.assign(std::size_t(raster.height), 0);
  end.assign(std::size_t(raster.height), 0);
  for(int r = 0; r < raster.height; ++r)
  {
    const std::uint64_t* row = raster.row(r);
    for(int x = next_bit(row, 0, raster.width, true); x < raster.width; x = next_bit(row, x, raster.width, true))
    {
      const int e = next_bit(row, x, raster.width, false);
      if(e - x > end[std::size_t(r)] - begin[std::size_t(r)])
      {
        begin[std::size_t(r)] = x;
        end[std::size_t(r)] = e;
      }
      x = e;
    }
  }
}

// The band of the rows [r0, r1) (at most 2^max_level rows, none empty) and the columns
// [b, e) common to their longest runs.
inline Mask_band make_mask_band(int r0, int r1, int b, int e)
{
  const int row_level = floor_log2(r1 - r0), level = floor_log2(e - b);
  return Mask_band{r0, r1 - (1 << row_level), row_level, b, e - b, e - (1 << level), level};
}

// Appends the bands of `raster` to `bands`, largest first: from each row down, the rows whose
// longest runs share at least 7/8 of the longest of them, at most 2^max_level rows. `begin`
// and `end` are scratch buffers.
inline void compute_mask_bands(const Raster_view& raster, int max_level, std::vector<Mask_band>& bands,
                               std::vector<int>& begin, std::vector<int>& end)
{
  longest_runs(raster, begin, end);
  const std::size_t first = bands.size();
  for(int r0 = 0; r0 < raster.height;)
  {
    int b = begin[std::size_t(r0)], e = end[std::size_t(r0)], longest = e - b, r1 = r0 + 1;
    for(; b < e && r1 < raster.height && r1 - r0 < (1 << max_level); ++r1)
    {
      const int nb = std::max(b, begin[std::size_t(r1)]), ne = std::min(e, end[std::size_t(r1)]);
      const int l = std::max(longest, end[std::size_t(r1)] - begin[std::size_t(r1)]);
      if(8 * (ne - nb) < 7 * l)
        break;
      b = nb;
      e = ne;
      longest = l;
    }
    if(b < e)
      bands.push_back(make_mask_band(r0, r1, b, e));
    r0 = r1;
  }
  std::sort(bands.begin() + std::ptrdiff_t(first), bands.end(), [](const Mask_band& x, const Mask_band& y) {
    const long long ax = (long long)(x.last_row - x.row + (1 << x.row_level)) * x.length;
    const long long ay = (long long)(y.last_row - y.row + (1 << y.row_level)) * y.length;
    return ax != ay ? ax > ay : x.row < y.row;
  });
}

// The 64 bits p .. p + 63 of a bit row of `words` words (zero outside).
inline std::uint64_t bits_at(const std::uint64_t* row, int words, int p)
{
  const int k = p >> 6, s = p & 63;
  const std::uint64_t low = k < words ? row[k] : 0;
  if(s == 0)
    return low;
  const std::uint64_t high = k + 1 < words ? row[k + 1] : 0;
  return (low >> s) | (high << (64 - s));
}

// The 64 bits p .. p + 63 of a bit row padded with zero words: its words p >> 6 and the next
// exist.
inline std::uint64_t padded_bits_at(const std::uint64_t* row, int p)
{
  const int k = p >> 6, s = p & 63;
  return (row[k] >> s) | ((row[k + 1] << 1) << (63 - s));
}

// The bits 0 .. n - 1 of a word (n in 0 .. 64).
inline std::uint64_t low_bits(int n) { return n >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1; }

// The bits p .. 63 of a word (0 when p >= 64).
inline std::uint64_t bits_from(int p) { return p >= 64 ? 0 : ~std::uint64_t(0) << p; }

// The longest run of set bits of a row of `width` bits: its length and start.
inline std::pair<int, int> longest_set_run(const std::uint64_t* row, int width)
{
  std::pair<int, int> longest(0, 0);
  for(int x = next_bit(row, 0, width, true); x < width; x = next_bit(row, x, width, true))
  {
    const int end = next_bit(row, x, width, false);
    if(end - x > longest.first)
      longest = std::make_pair(end - x, x);
    x = end;
  }
  return longest;
}

// A frame origin in atlas texels; x = -1: none.
struct Frame_position
{
  int x = -1;
  int y = -1;
};

// The texels first .. last of a row newly occupied, and `low`, the start of the free run that
// held `first` before (no free window starting before it meets them).
struct Changed_span
{
  int low = 0;
  int first = 0;
  int last = -1;
};

// The rows first .. last (none when first > last).
struct Row_range
{
  int first = std::numeric_limits<int>::max();
  int last = -1;
  void add(int r)
  {
    first = std::min(first, r);
    last = std::max(last, r);
  }
};

// The largest set bit of a row below `x`, or -1.
inline int previous_set_bit(const std::uint64_t* row, int x)
{
  if(x <= 0)
    return -1;
  int k = (x - 1) >> 6;
  std::uint64_t w = row[k] & low_bits(((x - 1) & 63) + 1);
  while(w == 0)
  {
    if(--k < 0)
      return -1;
    w = row[k];
  }
  return 64 * k + 63 - leading_zeros(w);
}

// The occupancy of the atlas: the occupied texels, the free windows V[k][m], their summaries
// and the longest free run of V[0][m] per row. At most 4096 texels per side (one summary word
// per row).
class Atlas_occupancy
{
public:
  static constexpr int max_size = 4096;

  // An empty atlas of `size` x `size` texels (size <= max_size), with bands of up to
  // 2^max_band_level rows.
  void reset(int size, int max_band_level)
  {
    CGAL_precondition(size >= 1 && size <= max_size);
    size_ = size;
    words_ = words_for_bits(size);
    stride_ = std::size_t(words_) + 2;
    group_level_ = 0;
    while((64 << group_level_) < size)
      ++group_level_;
    group_spread_.clear();
    for(std::uint64_t bits = 0; group_level_ >= 3 && bits < (std::uint64_t(1) << (64 >> group_level_)); ++bits)
    {
      std::uint64_t texels = 0;
      for(int i = 0; i < (64 >> group_level_); ++i)
        texels |= ((bits >> i) & 1u) ? low_bits(1 << group_level_) << (i << group_level_) : 0;
      group_spread_.push_back(texels);
    }
    group_low_bits_ = 0;
    group_multiplier_ = 0;
    for(int i = 0; i < (64 >> group_level_); ++i)
    {
      group_low_bits_ |= std::uint64_t(1) << (i << group_level_);
      group_multiplier_ |= std::uint64_t(1) << (64 - (64 >> group_level_) - i * ((1 << group_level_) - 1));
    }
    levels_ = floor_log2(size) + 1;
    row_levels_ = std::min(max_band_level, floor_log2(size)) + 1;
    const std::size_t tables = std::size_t(levels_) * std::size_t(row_levels_);
    bits_.assign(std::size_t(size) * stride_, 0);
    windows_.resize(tables * std::size_t(size) * stride_);  // written by start() (fill_empty())
    summaries_.resize(tables * std::size_t(size));
    floors_.assign(std::size_t(row_levels_) * std::size_t(size + 1), 0);
    longest_.resize(std::size_t(row_levels_) * std::size_t(size));
    changed_.assign(tables, Row_range());
    spans_.assign(std::size_t(size), Changed_span());
    lifetimes_.assign(tables, std::numeric_limits<int>::max());
    summary_lifetimes_.assign(tables, std::numeric_limits<int>::max());
    placed_ = 0;
  }

  // The number of tables of free windows (levels k, m).
  std::size_t table_count() const { return lifetimes_.size(); }
  std::size_t table(int level, int row_level) const { return std::size_t(level * row_levels_ + row_level); }

  // Computes the windows of the empty atlas (after reset()), and lets the windows of each
  // level (k, m) (index table(k, m)) go stale once `windows[t]` charts are placed, and their
  // summaries once `summaries[t]` charts are: the searches after that do not read them (the
  // lifetimes come from the masks still to place, packing.h). The levels that a level is
  // computed from, (k, m - 1) and (k - 1, 0) for m = 0, live as long as it; the levels (0, m)
  // (the longest free runs, read by every search) live for ever.
  void start(const std::vector<int>& windows, const std::vector<int>& summaries)
  {
    lifetimes_ = windows;
    summary_lifetimes_ = summaries;
    for(int m = 0; m < row_levels_; ++m)
      lifetimes_[table(0, m)] = std::numeric_limits<int>::max();
    for(int level = levels_ - 1; level >= 0; --level)
    {
      for(int m = row_levels_ - 1; m > 0; --m)
        lifetimes_[table(level, m - 1)] = std::max(lifetimes_[table(level, m - 1)], lifetimes_[table(level, m)]);
      if(level > 0)
        lifetimes_[table(level - 1, 0)] = std::max(lifetimes_[table(level - 1, 0)], lifetimes_[table(level, 0)]);
    }
    fill_empty();
  }

  // The first frame origin (smallest y, then smallest x) with x <= x_max and y <= y_max where
  // the mask fits; x = -1 when there is none.
  // The search starts at the row `y_start` (the rows above it known not to fit); `reach`
  // gets the first row not shown to be unfit: the row found, else y_max + 1 (the rows above
  // it stay unfit for this mask, and any mask that contains it, while the atlas only fills).
  Frame_position find(const Chart_mask& mask, int x_max, int y_max, int y_start, int& reach)
  {
    reach = y_start;
    if(x_max < 0 || y_max < 0)
      return Frame_position();
    int y = std::max(y_start, first_row(mask));
    for(; y <= y_max; ++y)
    {
      if(!bands_may_fit(mask, y))
        continue;
      const int x = first_fit_in_row(mask, y, x_max);
      if(x <= x_max)
      {
        reach = y;
        return Frame_position{x, y};
      }
    }
    reach = y;
    return Frame_position();
  }

  // Occupies the set cells of `cells` at the frame origin (x, y) (inside the atlas).
  void place(const Raster_view& cells, int x, int y)
  {
    const int base = x >> 6, shift = x & 63;
    Changed_span all{size_, size_, -1};  // the union of the rows' spans
    for(int r = 0; r < cells.height; ++r)
    {
      const std::uint64_t* m = cells.row(r);
      std::uint64_t* a = row(y + r);
      const int first = next_bit(m, 0, cells.width, true);
      Changed_span& span = spans_[std::size_t(y + r)];
      span = Changed_span{0, 0, -1};
      if(first == cells.width)
        continue;
      span = Changed_span{previous_set_bit(a, x + first) + 1, x + first, x + cells.width - 1};
      all = Changed_span{std::min(all.low, span.low), std::min(all.first, span.first), span.last};
      for(int k = 0; k < cells.words; ++k)
      {
        a[base + k] |= m[k] << shift;
        a[base + k + 1] |= (m[k] >> 1) >> (63 - shift);
      }
    }
    ++placed_;
    update_rows(y, y + cells.height - 1, all);
  }

private:
  // The windows, summaries and longest free runs of the empty atlas, of every level (those
  // that update_rows() computes from empty rows, written directly: start() runs once per
  // trial density, and computing them row by row took most of a trial's placement of a few
  // charts). V[k][m] at the row r: the origins x <= size - 2^k when r + 2^m <= size, else none.
  void fill_empty()
  {
    for(int m = 0; m < row_levels_; ++m)
      for(int level = 0; level < levels_; ++level)
      {
        const std::size_t t = table(level, m);
        const int origins = size_ - (1 << level) + 1;
        const std::uint64_t groups = low_bits((origins + (1 << group_level_) - 1) >> group_level_);
        for(int r = 0; r < size_; ++r)
        {
          const bool inside = r + (1 << m) <= size_;
          std::uint64_t* w = window(t, r);
          for(int k = 0; k < int(stride_); ++k)
            w[k] = (inside && origins > 64 * k) ? low_bits(origins - 64 * k) : 0;
          summaries_[t * std::size_t(size_) + std::size_t(r)] = inside ? groups : 0;
          if(level == 0)
            longest(m, r) = inside ? std::make_pair(size_, 0) : std::make_pair(0, 0);
        }
      }
  }

  // Whether the windows of the table t are read again.
  bool alive(std::size_t t) const { return lifetimes_[t] > placed_; }
  std::uint64_t* row(int r) { return bits_.data() + std::size_t(r) * stride_; }
  const std::uint64_t* window(std::size_t t, int r) const
  {
    return windows_.data() + (t * std::size_t(size_) + std::size_t(r)) * stride_;
  }
  std::uint64_t* window(std::size_t t, int r)
  {
    return windows_.data() + (t * std::size_t(size_) + std::size_t(r)) * stride_;
  }
  std::uint64_t summary(std::size_t t, int r) const { return summaries_[t * std::size_t(size_) + std::size_t(r)]; }
  std::pair<int, int>& longest(int row_level, int r)
  {
    return longest_[std::size_t(row_level) * std::size_t(size_) + std::size_t(r)];
  }

  // The words of level k whose bits may change when the texels span.first .. span.last of a
  // row are occupied: the windows that meet them, and start in the free run they were in.
  void level_words(int level, const Changed_span& span, int& w0, int& w1) const
  {
    w0 = std::max(span.low, span.first - (1 << level) + 1) >> 6;
    w1 = std::min(words_ - 1, span.last >> 6);
  }

  // The summary bits of the words w0 .. w1 of a window row: bit j when its texels j 2^g ..
  // (j + 1) 2^g - 1 hold a set bit (g = group_level_ <= 6: a word holds 64 / 2^g groups).
  void update_summary(std::size_t t, int r, int w0, int w1)
  {
    const std::uint64_t* w = window(t, r);
    const int per_word = 64 >> group_level_;
    std::uint64_t bits = 0;
    for(int k = w0; k <= w1; ++k)
      bits |= group_bits(w[k]) << (k * per_word);
    const std::uint64_t changed = low_bits((w1 + 1) * per_word) & bits_from(w0 * per_word);
    std::uint64_t& s = summaries_[t * std::size_t(size_) + std::size_t(r)];
    s = (s & ~changed) | bits;
  }

  // The bit i set when the group i of the word (its bits i 2^g .. (i + 1) 2^g - 1) is not zero.
  // For g >= 3 the lowest bits of the groups are gathered by one product (group_multiplier_:
  // its partial products fall on distinct bits, so nothing carries).
  std::uint64_t group_bits(std::uint64_t word) const
  {
    const int g = group_level_, per_word = 64 >> g;
    for(int shift = 1; shift < (1 << g); shift <<= 1)
      word |= word >> shift;
    word &= group_low_bits_;
    if(g >= 3)
      return (word * group_multiplier_) >> (64 - per_word);
    std::uint64_t bits = 0;
    for(int i = 0; i < per_word; ++i)
      bits |= ((word >> (i << g)) & 1u) << i;
    return bits;
  }

  // The longest run of V[0][m] at the row r, after the texels of the span were occupied:
  // scanned again only when they meet the longest run kept.
  void update_longest(int row_level, int r, const Changed_span& span)
  {
    std::pair<int, int>& l = longest(row_level, r);
    if(span.first < l.second + l.first && l.second <= span.last)
      l = longest_set_run(window(table(0, row_level), r), size_);
  }

  // Writes value(k) into the words a .. b of the window row (t, r) and updates the summary of
  // the words that changed; whether one did.
  template <class Value>
  bool rewrite_words(std::size_t t, int r, int a, int b, const Value& value)
  {
    std::uint64_t* w = window(t, r);
    int first = b + 1, last = a - 1;
    for(int k = a; k <= b; ++k)
    {
      const std::uint64_t v = value(k);
      if(v == w[k])
        continue;
      w[k] = v;
      first = std::min(first, k);
      last = k;
    }
    if(first <= last && summary_lifetimes_[t] > placed_)
      update_summary(t, r, first, last);
    return first <= last;
  }

  // The windows W_k = V[k][0] of the row y, for the texels of the span occupied: a level changes
  // only where the level below it did. Extends the rows changed of each level (`changed_`).
  void update_row_levels(int y, const Changed_span& span)
  {
    const std::uint64_t* occupied = row(y);
    int a = 0, b = 0;
    level_words(0, span, a, b);
    bool changed = rewrite_words(table(0, 0), y, a, b, [&](int k) {
      return ~occupied[k] & (k == words_ - 1 ? low_bits(size_ - 64 * k) : ~std::uint64_t(0));
    });
    if(changed)
      changed_[table(0, 0)].add(y);
    if(changed)
      update_longest(0, y, span);
    for(int level = 1; level < levels_ && changed && alive(table(level, 0)); ++level)
    {
      const std::uint64_t* previous = window(table(level - 1, 0), y);
      level_words(level, span, a, b);
      changed = rewrite_words(table(level, 0), y, a, b, [&](int k) {
        return previous[k] & bits_at(previous, words_, 64 * k + (1 << (level - 1)));
      });
      if(changed)
        changed_[table(level, 0)].add(y);
    }
  }

  // The windows V[k][m], m >= 1, of the rows whose blocks meet the rows changed of the levels
  // (k, m - 1) (`span`: the union of the spans of the rows occupied).
  void update_row_blocks(const Changed_span& span)
  {
    for(int m = 1; m < row_levels_; ++m)
    {
      const int half = 1 << (m - 1);
      for(int level = 0; level < levels_; ++level)
      {
        const Row_range below = changed_[table(level, m - 1)];
        if(below.first > below.last || !alive(table(level, m)))
          continue;
        int a = 0, b = 0;
        level_words(level, span, a, b);
        const std::size_t previous = table(level, m - 1), current = table(level, m);
        const int r0 = std::max(0, below.first - 2 * half + 1), r1 = std::min(below.last, size_ - 2 * half);
        for(int r = r0; r <= r1; ++r)
        {
          const std::uint64_t *top = window(previous, r), *bottom = window(previous, r + half);
          const bool changed = rewrite_words(current, r, a, b, [&](int k) { return top[k] & bottom[k]; });
          if(changed)
            changed_[current].add(r);
          if(level == 0 && changed)
            update_longest(m, r, span);
        }
      }
    }
  }

  // The windows after the rows y0 .. y1 changed: each row in its span (spans_), the blocks
  // in the union `span` of them.
  void update_rows(int y0, int y1, const Changed_span& span)
  {
    std::fill(changed_.begin(), changed_.end(), Row_range());
    for(int y = y0; y <= y1; ++y)
      if(spans_[std::size_t(y)].first <= spans_[std::size_t(y)].last)
        update_row_levels(y, spans_[std::size_t(y)]);
    if(span.first <= span.last)
      update_row_blocks(span);
  }

  // The first row whose rows .. + 2^m - 1 hold a free run of `length` columns (size_ when
  // none); it only grows (placing only shortens free runs), so it is kept between searches.
  int floor_row(int row_level, int length)
  {
    int& y = floors_[std::size_t(row_level) * std::size_t(size_ + 1) + std::size_t(length)];
    while(y < size_ && longest(row_level, y).first < length)
      ++y;
    return y;
  }

  // The lowest frame row that every band of the mask allows.
  int first_row(const Chart_mask& mask)
  {
    int y = 0;
    for(int i = 0; i < mask.band_count; ++i)
    {
      const Mask_band& band = mask.bands[i];
      y = std::max(y, floor_row(band.row_level, band.length) - band.row);
    }
    return y;
  }

  // Whether, for every band of the mask at the frame row y, its rows hold a free run of
  // columns as long as the band (somewhere).
  bool bands_may_fit(const Chart_mask& mask, int y)
  {
    for(int i = 0; i < mask.band_count; ++i)
    {
      const Mask_band& band = mask.bands[i];
      if(longest(band.row_level, y + band.row).first < band.length
         || longest(band.row_level, y + band.last_row).first < band.length)
        return false;
    }
    return true;
  }

  // The bit j set when the window row of summary `s` may have a bit at p + j 2^g (in its
  // group (p >> g) + j or the next).
  std::uint64_t summary_at(std::uint64_t s, int p) const
  {
    const int group = p >> group_level_;
    return group >= 64 ? 0 : (s >> group) | ((s >> 1) >> group);
  }

  // The groups of x where every band of the mask may be free at the frame row y (by the
  // summaries).
  std::uint64_t candidate_groups(const Chart_mask& mask, int y) const
  {
    std::uint64_t candidates = ~std::uint64_t(0);
    for(int i = 0; i < mask.band_count && candidates != 0; ++i)
    {
      const Mask_band& band = mask.bands[i];
      const std::size_t t = table(band.level, band.row_level);
      const std::uint64_t top = summary(t, y + band.row), bottom = summary(t, y + band.last_row);
      candidates &= summary_at(top, band.start) & summary_at(top, band.tail) & summary_at(bottom, band.start)
                    & summary_at(bottom, band.tail);
    }
    return candidates;
  }

  // The texels of the 64 from the group `group` that lie in the candidate groups.
  std::uint64_t group_texels(std::uint64_t groups, int group) const
  {
    const int g = group_level_, per_word = 64 >> g;
    const std::uint64_t bits = (groups >> group) & low_bits(per_word);
    if(!group_spread_.empty())
      return group_spread_[std::size_t(bits)];
    std::uint64_t texels = 0;
    for(int i = 0; i < per_word; ++i)
      if((bits >> i) & 1u)
        texels |= low_bits(1 << g) << (i << g);
    return texels;
  }

  // The x = base + bit (among `candidates`) where every band of the mask is free at the
  // frame row y.
  std::uint64_t band_bits(const Chart_mask& mask, int y, int base, std::uint64_t candidates) const
  {
    for(int i = 0; i < mask.band_count && candidates != 0; ++i)
    {
      const Mask_band& band = mask.bands[i];
      const std::size_t t = table(band.level, band.row_level);
      const std::uint64_t *top = window(t, y + band.row), *bottom = window(t, y + band.last_row);
      candidates &= padded_bits_at(top, base + band.start) & padded_bits_at(top, base + band.tail)
                    & padded_bits_at(bottom, base + band.start) & padded_bits_at(bottom, base + band.tail);
    }
    return candidates;
  }

  // The x = base + bit (among `candidates`) where every run of the mask is free at the row y.
  std::uint64_t run_bits(const Chart_mask& mask, int y, int base, std::uint64_t candidates) const
  {
    for(int i = 0; i < mask.run_count && candidates != 0; ++i)
    {
      const Mask_run& run = mask.runs[i];
      const std::uint64_t* w = window(table(run.level, 0), y + run.row);
      candidates &= padded_bits_at(w, base + run.start) & padded_bits_at(w, base + run.tail);
    }
    return candidates;
  }

  // The first x <= x_max where the mask fits at the frame row y, or x_max + 1.
  int first_fit_in_row(const Chart_mask& mask, int y, int x_max) const
  {
    const int g = group_level_, step = 64 >> g;
    std::uint64_t groups = candidate_groups(mask, y) & low_bits((x_max >> g) + 1);
    while(groups != 0)
    {
      const int group = lowest_bit(groups), base = group << g;
      std::uint64_t bits = band_bits(mask, y, base, low_bits(x_max - base + 1) & group_texels(groups, group));
      bits = run_bits(mask, y, base, bits);
      if(bits != 0)
        return base + lowest_bit(bits);
      groups &= ~(low_bits(step) << group);
    }
    return x_max + 1;
  }

  int size_ = 0;
  int words_ = 0;
  std::size_t stride_ = 0;  // words per row: words_ and two zero words
  int group_level_ = 0;     // a summary bit stands for 2^group_level_ texels (64 groups at most)
  std::uint64_t group_low_bits_ = 0;    // the lowest bit of every group
  std::uint64_t group_multiplier_ = 0;  // gathers them (group_bits())
  std::vector<std::uint64_t> group_spread_;  // for g >= 3: the texels of each set of the groups of a word
  int levels_ = 0;          // k = 0 .. levels_ - 1
  int row_levels_ = 0;      // m = 0 .. row_levels_ - 1
  std::vector<std::uint64_t> bits_;       // occupied texels: size_ rows
  std::vector<std::uint64_t> windows_;    // V[k][m]: per (k, m), size_ rows
  std::vector<std::uint64_t> summaries_;  // per (k, m) and row: bit j when its word j is not 0
  std::vector<int> floors_;               // per m and length: no free run above this row
  std::vector<std::pair<int, int> > longest_;  // per m and row: the longest run of V[0][m] (length, start)
  std::vector<Row_range> changed_;        // per (k, m): the rows changed by the current update
  std::vector<Changed_span> spans_;       // per row: its span in the current update
  std::vector<int> lifetimes_;            // per (k, m): kept up to date while fewer charts are placed
  std::vector<int> summary_lifetimes_;    // per (k, m): the same for its summaries
  int placed_ = 0;                        // charts placed
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PLACEMENT_H
