#pragma once
// Sobol's sequence in base 2 (I. M. Sobol', "On the distribution of points in a cube and
// the approximate evaluation of integrals", 1967), its first two dimensions. They form a
// (0,2)-sequence: the points with indices in [k 2^m, (k + 1) 2^m) -- the first 2^m among
// them -- are a (0,m,2)-net, that is every box
//   [a 2^-p, (a + 1) 2^-p) x [b 2^-q, (b + 1) 2^-q),   p + q = m
// (an "elementary interval" of area 2^-m) holds exactly one of them. That is jittered
// sampling of an n x n grid, of a 1 x N and an N x 1 grid and of every 2^p x 2^q grid
// between, all at once, and it holds after every power of two of samples.
//
// Point i in dimension j, as the binary digits of a fraction, is the exclusive or of one
// direction number per set bit of i:
//   x_j(i) = b_1 v_1 xor b_2 v_2 xor b_3 v_3 xor ...,   i = b_1 + 2 b_2 + 4 b_3 + ...
// with v_k = m_k / 2^k, m_k odd and below 2^k. From a primitive polynomial over GF(2)
//   x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1
// and s initial numbers m_1 ... m_s, the others follow (Bratley and Fox, 1988):
//   m_k = 2 a_1 m_(k-1) xor 2^2 a_2 m_(k-2) xor ... xor 2^(s-1) a_(s-1) m_(k-s+1)
//         xor 2^s m_(k-s) xor m_(k-s)
// Dimension 0 is van der Corput's radical inverse (every m_k = 1, so v_k = 2^-k: the bits
// of i mirrored about the binary point); dimension 1 is the polynomial x + 1 with
// m_1 = 1, the first line of Joe and Kuo's table (S. Joe and F. Y. Kuo, "Constructing
// Sobol sequences with better two-dimensional projections", 2008: d = 2 of their
// file new-joe-kuo-6.21201). Its first points are 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
#include <cstdint>

namespace gi {

// The 32 binary digits of x_j(i), dimension j = 0 or 1: the fraction is the value
// times 2^-32. Throws std::invalid_argument for another dimension.
std::uint32_t sobol(std::uint32_t index, int dimension);

}  // namespace gi
