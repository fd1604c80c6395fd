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
// The atlas is a square of `resolution` texels, padded by the gutter g on every side (the
// padding is never occupied: a chart's gutter may reach beyond the atlas, its texels may not).
// A chart is a frame of (w + 2g) x (h + 2g) cells: its own cells T at [g, g+w) x [g, g+h)
// and its dilated cells D = dilate(T, g). A frame origin (X, Y) in padded coordinates puts
// T at the atlas texels [X, X+w) x [Y, Y+h), so 0 <= X <= resolution - w; the chart fits
// where D meets no occupied texel, and placing it occupies T.
//
// D is its runs of set bits: (row r, start a, length L). D fits at (X, Y) exactly when, for
// every run, the atlas texels X+a .. X+a+L-1 of the row Y+r are free. The atlas keeps, for
// every row and every k with 2^k <= its size, the bit row W_k: bit p set when the texels
// p .. p + 2^k - 1 are all free (W_0 is the free texels, W_k = W_{k-1} & (W_{k-1} >> 2^{k-1})).
// With 2^k <= L < 2^{k+1}, the two windows of length 2^k at a and at a + L - 2^k cover the run:
// the run is free at X exactly when W_k has the bits X+a and X+a+L-2^k. So a row Y tests 64
// values of X at once: the AND over the runs of W_k shifted by the two offsets, stopped as soon
// as it is zero (the longest runs first: they fail first). A summary of W_k (bit j: the word j
// of W_k is not zero) tests 64 words of X at once first: X in the word j can fit only if, for
// every run, W_k has a bit in the word j + (a >> 6) or the next. The rows Y are scanned from the
// top, and a row is passed over at once when some row of D has a run longer than the longest
// free run of the atlas row it would cover (when that free run is shorter than the longest run
// of every row of D, all the rows up to it are passed over).

#include <CGAL/Surface_mesh_parameterization/internal/atlas/raster.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
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

// A run of set bits of a dilated chart raster: the bits start .. start + length - 1 of a row;
// `level` = floor(log2(length)), `tail` = start + length - 2^level.
struct Mask_run
{
  int row = 0;
  int start = 0;
  int length = 0;
  int level = 0;
  int tail = 0;
};

// The runs of a dilated chart raster, longest first, and the longest run of each row.
struct Mask_runs
{
  const Mask_run* runs = nullptr;
  int count = 0;
  const int* row_longest = nullptr;  // per row
  int shortest = 0;                  // the smallest of row_longest
};

// Appends the runs of `raster` to `runs` (sorted longest first, ties by row and start) and
// writes the longest run of each row to `row_longest`.
inline void compute_mask_runs(const Raster_view& raster, std::vector<Mask_run>& runs, int* row_longest)
{
  const std::size_t first = runs.size();
  for(int r = 0; r < raster.height; ++r)
  {
    const std::uint64_t* row = raster.row(r);
    row_longest[r] = 0;
    for(int x = next_bit(row, 0, raster.width, true); x < raster.width; x = next_bit(row, x, raster.width, true))
    {
      const int end = next_bit(row, x, raster.width, false), level = floor_log2(end - x);
      runs.push_back(Mask_run{r, x, end - x, level, end - (1 << level)});
      row_longest[r] = std::max(row_longest[r], end - x);
      x = end;
    }
  }
  std::sort(runs.begin() + std::ptrdiff_t(first), runs.end(), [](const Mask_run& a, const Mask_run& b) {
    return a.length != b.length ? a.length > b.length : (a.row != b.row ? a.row < b.row : a.start < b.start);
  });
}

// The longest run of clear bits of a row of `width` bits.
inline int longest_clear_run(const std::uint64_t* row, int width)
{
  int longest = 0;
  for(int x = next_bit(row, 0, width, false); x < width; x = next_bit(row, x, width, false))
  {
    const int end = next_bit(row, x, width, true);
    longest = std::max(longest, end - x);
    x = end;
  }
  return longest;
}

// The 64 bits p .. p + 63 of a bit row (zero beyond its words).
inline std::uint64_t bits_at(const std::uint64_t* row, int words, int p)
{
  const int k = p >> 6, s = p & 63;
  const std::uint64_t low = k < words ? row[k] : 0;
  if(s == 0)
    return low;
  const std::uint64_t high = k + 1 < words ? row[k + 1] : 0;
  return (low >> s) | (high << (64 - s));
}

// A frame origin in padded atlas coordinates.
struct Frame_position
{
  int x = -1;
  int y = -1;
};

class Atlas_occupancy
{
public:
  // An empty atlas of `size` x `size` padded texels.
  void reset(int size)
  {
    size_ = size;
    words_ = words_for_bits(size);
    levels_ = floor_log2(size) + 1;
    summary_words_ = words_for_bits(words_);
    bits_.assign(std::size_t(size) * std::size_t(words_), 0);
    windows_.assign(std::size_t(levels_) * bits_.size(), 0);
    summaries_.assign(std::size_t(levels_) * std::size_t(size) * std::size_t(summary_words_), 0);
    longest_free_.assign(std::size_t(size), size);
    for(int y = 0; y < size; ++y)
      update_windows(y);
  }

  // The first frame origin (smallest y, then smallest x) with x <= x_max, y <= y_max where
  // the dilated raster of `height` rows and runs `mask` fits; x = -1 when there is none.
  Frame_position find(const Mask_runs& mask, int height, int x_max, int y_max) const
  {
    for(int y = 0; y <= y_max;)
    {
      const int next_y = rows_skip(mask, height, y);
      if(next_y > y)
      {
        y = next_y;
        continue;
      }
      const int x = first_fit_in_row(mask, y, x_max);
      if(x <= x_max)
        return Frame_position{x, y};
      ++y;
    }
    return Frame_position();
  }

  // Occupies the set cells of `cells` at the frame origin (x, y).
  void place(const Raster_view& cells, int x, int y)
  {
    const int base = x >> 6, shift = x & 63;
    for(int r = 0; r < cells.height; ++r)
    {
      const std::uint64_t* m = cells.row(r);
      std::uint64_t* a = row(y + r) + base;
      bool changed = false;
      for(int k = 0; k < cells.words; ++k)
      {
        if(m[k] == 0)
          continue;
        changed = true;
        a[k] |= m[k] << shift;
        if(shift != 0 && (m[k] >> (64 - shift)) != 0)
          a[k + 1] |= m[k] >> (64 - shift);
      }
      if(changed)
        update_windows(y + r);
    }
  }

private:
  std::uint64_t* row(int r) { return bits_.data() + std::size_t(r) * std::size_t(words_); }
  const std::uint64_t* window(int level, int r) const
  {
    return windows_.data() + (std::size_t(level) * std::size_t(size_) + std::size_t(r)) * std::size_t(words_);
  }
  std::uint64_t* summary(int level, int r)
  {
    return summaries_.data() + (std::size_t(level) * std::size_t(size_) + std::size_t(r)) * std::size_t(summary_words_);
  }
  const std::uint64_t* summary(int level, int r) const
  {
    return summaries_.data() + (std::size_t(level) * std::size_t(size_) + std::size_t(r)) * std::size_t(summary_words_);
  }

  // Recomputes the windows W_k and the longest free run of the row y.
  void update_windows(int y)
  {
    std::uint64_t* w0 = const_cast<std::uint64_t*>(window(0, y));
    const std::uint64_t* occupied = row(y);
    for(int k = 0; k < words_; ++k)
      w0[k] = ~occupied[k];
    if((size_ & 63) != 0)
      w0[words_ - 1] &= ~(~std::uint64_t(0) << (size_ & 63));
    for(int level = 1; level < levels_; ++level)
    {
      const std::uint64_t* previous = window(level - 1, y);
      std::uint64_t* current = const_cast<std::uint64_t*>(window(level, y));
      for(int k = 0; k < words_; ++k)
        current[k] = previous[k] & bits_at(previous, words_, 64 * k + (1 << (level - 1)));
    }
    for(int level = 0; level < levels_; ++level)
    {
      const std::uint64_t* w = window(level, y);
      std::uint64_t* s = summary(level, y);
      std::fill(s, s + summary_words_, 0);
      for(int k = 0; k < words_; ++k)
        s[k >> 6] |= std::uint64_t(w[k] != 0) << (k & 63);
    }
    longest_free_[std::size_t(y)] = longest_clear_run(occupied, size_);
  }

  // y when every row of the mask has a free run as long as its longest run at the row y;
  // otherwise a larger y: past the last atlas row that no mask row fits (its longest free run
  // is shorter than every row's longest run), or y + 1.
  int rows_skip(const Mask_runs& mask, int height, int y) const
  {
    for(int r = height - 1; r >= 0; --r)
      if(longest_free_[std::size_t(y + r)] < mask.shortest)
        return y + r + 1;
    for(int r = 0; r < height; ++r)
      if(mask.row_longest[r] > longest_free_[std::size_t(y + r)])
        return y + 1;
    return y;
  }

  // The bits of the words of x (64 words from `first_word`) that may hold an x where every
  // run of the mask is free at the row y: the summaries of the runs' windows, ANDed.
  std::uint64_t candidate_words(const Mask_runs& mask, int y, int first_word) const
  {
    std::uint64_t candidates = ~std::uint64_t(0);
    for(int i = 0; i < mask.count && candidates != 0; ++i)
    {
      const Mask_run& run = mask.runs[i];
      const std::uint64_t* s = summary(run.level, y + run.row);
      const int head = first_word + (run.start >> 6), tail = first_word + (run.tail >> 6);
      candidates &= (bits_at(s, summary_words_, head) | bits_at(s, summary_words_, head + 1)) &
                    (bits_at(s, summary_words_, tail) | bits_at(s, summary_words_, tail + 1));
    }
    return candidates;
  }

  // The x of the word that start at `base` where every run of the mask is free at the row y
  // (a bit per x).
  std::uint64_t candidate_bits(const Mask_runs& mask, int y, int base) const
  {
    std::uint64_t candidates = ~std::uint64_t(0);
    for(int i = 0; i < mask.count && candidates != 0; ++i)
    {
      const Mask_run& run = mask.runs[i];
      const std::uint64_t* w = window(run.level, y + run.row);
      candidates &= bits_at(w, words_, base + run.start) & bits_at(w, words_, base + run.tail);
    }
    return candidates;
  }

  // The first x <= x_max where every run of the mask is free at the row y, or x_max + 1.
  int first_fit_in_row(const Mask_runs& mask, int y, int x_max) const
  {
    const int last_word = x_max >> 6;
    for(int first_word = 0; first_word <= last_word; first_word += 64)
    {
      std::uint64_t words = candidate_words(mask, y, first_word);
      if(last_word - first_word < 63)
        words &= ~std::uint64_t(0) >> (63 - (last_word - first_word));
      for(; words != 0; words &= words - 1)
      {
        const int base = 64 * (first_word + lowest_bit(words));
        std::uint64_t candidates = candidate_bits(mask, y, base);
        if(x_max - base < 63)
          candidates &= ~std::uint64_t(0) >> (63 - (x_max - base));
        if(candidates != 0)
          return base + lowest_bit(candidates);
      }
    }
    return x_max + 1;
  }

  int size_ = 0;
  int words_ = 0;
  int levels_ = 0;
  std::vector<std::uint64_t> bits_;     // occupied texels, size_ rows of words_ words
  std::vector<std::uint64_t> windows_;  // W_k for every level k and row
  int summary_words_ = 0;
  std::vector<std::uint64_t> summaries_;  // per level and row: bit j when the word j of W_k is not 0
  std::vector<int> longest_free_;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PLACEMENT_H
