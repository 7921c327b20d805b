#pragma once
// FNV-1a hashes of simcli's exit status and output for every case of
// test_output_hashes.cpp, in its order, recorded with a trusted build (the
// commit that last changed this file says which and why; CHANGELOG.md lists
// the changes of output).
// Regenerate only from a trusted build:
//   build/tests/test_output_hashes --generate path/to/simcli

#include <cstdint>

inline constexpr std::uint64_t expected_output_hashes[] = {
    0x0cd27d76e85fb46bULL,  // corner --broadphase brute -t 1
    0x0cd27d76e85fb46bULL,  // corner --broadphase grid -t 1
    0x0cd27d76e85fb46bULL,  // corner --broadphase grid -t 2
    0x0cd27d76e85fb46bULL,  // corner --grid 4 -t 2
    0x0cd27d76e85fb46bULL,  // corner --substeps 3 -t 2
    0x0cd27d76e85fb46bULL,  // corner --engine exact
    0x61d83cf4ee5ef0b5ULL,  // crossing --broadphase brute -t 1
    0x61d83cf4ee5ef0b5ULL,  // crossing --broadphase grid -t 1
    0x61d83cf4ee5ef0b5ULL,  // crossing --broadphase grid -t 2
    0x61d83cf4ee5ef0b5ULL,  // crossing --grid 4 -t 2
    0x61d83cf4ee5ef0b5ULL,  // crossing --substeps 3 -t 2
    0x61d83cf4ee5ef0b5ULL,  // crossing --engine exact
    0xedb153eebea273e5ULL,  // default --broadphase grid -t 1
    0xedb153eebea273e5ULL,  // default --broadphase grid -t 2
    0xedb153eebea273e5ULL,  // default --grid 4 -t 2
    0xd66a45970f30a889ULL,  // default --engine exact
    0x427dde8262709044ULL,  // faster_than_box --broadphase brute -t 1
    0x427dde8262709044ULL,  // faster_than_box --broadphase grid -t 1
    0x427dde8262709044ULL,  // faster_than_box --broadphase grid -t 2
    0x427dde8262709044ULL,  // faster_than_box --grid 4 -t 2
    0xc2dce5d3396d92deULL,  // faster_than_box --substeps 3 -t 2
    0xc2dce5d3396d92deULL,  // faster_than_box --engine exact
    0xba8686522f859d3aULL,  // glancing_line --broadphase brute -t 1
    0xba8686522f859d3aULL,  // glancing_line --broadphase grid -t 1
    0xba8686522f859d3aULL,  // glancing_line --broadphase grid -t 2
    0xba8686522f859d3aULL,  // glancing_line --grid 4 -t 2
    0xba8686522f859d3aULL,  // glancing_line --substeps 3 -t 2
    0xba8686522f859d3aULL,  // glancing_line --engine exact
    0xb8d65fff6642b27dULL,  // head_on --broadphase brute -t 1
    0xb8d65fff6642b27dULL,  // head_on --broadphase grid -t 1
    0xb8d65fff6642b27dULL,  // head_on --broadphase grid -t 2
    0xb8d65fff6642b27dULL,  // head_on --grid 4 -t 2
    0x7351a829f42b98f3ULL,  // head_on --substeps 3 -t 2
    0xb8d65fff6642b27dULL,  // head_on --engine exact
    0xc3017f4a11c6e948ULL,  // newtons_cradle --broadphase brute -t 1
    0xc3017f4a11c6e948ULL,  // newtons_cradle --broadphase grid -t 1
    0xc3017f4a11c6e948ULL,  // newtons_cradle --broadphase grid -t 2
    0xc3017f4a11c6e948ULL,  // newtons_cradle --grid 4 -t 2
    0xaa1764e0d8cc00d5ULL,  // newtons_cradle --substeps 3 -t 2
    0x9cebd7c3ff0c4495ULL,  // newtons_cradle --engine exact
    0xa9d3e0b36cd2dda3ULL,  // square --broadphase brute -t 1
    0xa9d3e0b36cd2dda3ULL,  // square --broadphase grid -t 1
    0xa9d3e0b36cd2dda3ULL,  // square --broadphase grid -t 2
    0xa9d3e0b36cd2dda3ULL,  // square --grid 4 -t 2
    0x7ae2dccae9b96a7fULL,  // square --substeps 3 -t 2
    0x3bc9b1ed3ec351f3ULL,  // square --engine exact
    0x54a68d8f41481500ULL,  // triangle --broadphase brute -t 1
    0x54a68d8f41481500ULL,  // triangle --broadphase grid -t 1
    0x54a68d8f41481500ULL,  // triangle --broadphase grid -t 2
    0x54a68d8f41481500ULL,  // triangle --grid 4 -t 2
    0x3c62e56afe8465f2ULL,  // triangle --substeps 3 -t 2
    0x5d78a839ed674330ULL,  // triangle --engine exact
    0xa6464b00b719c0deULL,  // wall_then_pair --broadphase brute -t 1
    0xa6464b00b719c0deULL,  // wall_then_pair --broadphase grid -t 1
    0xa6464b00b719c0deULL,  // wall_then_pair --broadphase grid -t 2
    0xa6464b00b719c0deULL,  // wall_then_pair --grid 4 -t 2
    0x4ce26f2674f563e0ULL,  // wall_then_pair --substeps 3 -t 2
    0x4ce26f2674f563e0ULL,  // wall_then_pair --engine exact
    0xddb83e94aeddc10dULL,  // random 0 (N 25, L 100, r 5.0462650440403207, S 24) --broadphase brute -t 1
    0xddb83e94aeddc10dULL,  // random 0 (N 25, L 100, r 5.0462650440403207, S 24) --broadphase grid -t 1
    0xad2167bd6a734c42ULL,  // random 0 (N 25, L 100, r 5.0462650440403207, S 24) --substeps 2 -t 2
    0xbd406ca44c2872a5ULL,  // random 0 (N 25, L 100, r 5.0462650440403207, S 24) --engine exact
    0x584bf7341e35485eULL,  // random 1 (N 12, L 1000, r 23.032943298089034, S 18) --broadphase brute -t 1
    0x584bf7341e35485eULL,  // random 1 (N 12, L 1000, r 23.032943298089034, S 18) --broadphase grid -t 2
    0xf7072492ab8ad926ULL,  // random 1 (N 12, L 1000, r 23.032943298089034, S 18) --substeps 3 -t 2
    0x443100a0fceb3895ULL,  // random 1 (N 12, L 1000, r 23.032943298089034, S 18) --engine exact
    0x246de944f0294e58ULL,  // random 2 (N 3, L 100, r 4.6065886596178069, S 18) --broadphase brute -t 1
    0x246de944f0294e58ULL,  // random 2 (N 3, L 100, r 4.6065886596178069, S 18) --broadphase grid -t 1
    0x6c6b81ab6205f8bdULL,  // random 2 (N 3, L 100, r 4.6065886596178069, S 18) --substeps 4 -t 2
    0x85f66c5f552fd66dULL,  // random 2 (N 3, L 100, r 4.6065886596178069, S 18) --engine exact
    0x15acc480e8202c3bULL,  // random 3 (N 7, L 250, r 3.7696502193256718, S 3) --broadphase brute -t 1
    0x15acc480e8202c3bULL,  // random 3 (N 7, L 250, r 3.7696502193256718, S 3) --broadphase grid -t 2
    0x15acc480e8202c3bULL,  // random 3 (N 7, L 250, r 3.7696502193256718, S 3) --substeps 2 -t 2
    0x15acc480e8202c3bULL,  // random 3 (N 7, L 250, r 3.7696502193256718, S 3) --engine exact
    0xde7af8b85b2a4d40ULL,  // random 4 (N 37, L 250, r 1.6396426722821356, S 7) --broadphase brute -t 1
    0xde7af8b85b2a4d40ULL,  // random 4 (N 37, L 250, r 1.6396426722821356, S 7) --broadphase grid -t 1
    0x67b83803440897f7ULL,  // random 4 (N 37, L 250, r 1.6396426722821356, S 7) --substeps 3 -t 2
    0x73bc72bffd689c62ULL,  // random 4 (N 37, L 250, r 1.6396426722821356, S 7) --engine exact
    0x9b16b7611dbbe063ULL,  // random 5 (N 27, L 100, r 6.4235809836456754, S 8) --broadphase brute -t 1
    0x9b16b7611dbbe063ULL,  // random 5 (N 27, L 100, r 6.4235809836456754, S 8) --broadphase grid -t 2
    0x0d14a9d12e24ff23ULL,  // random 5 (N 27, L 100, r 6.4235809836456754, S 8) --substeps 4 -t 2
    0xd89a292d460b4838ULL,  // random 5 (N 27, L 100, r 6.4235809836456754, S 8) --engine exact
    0x04bd87ff49d02f47ULL,  // random 6 (N 56, L 100, r 4.4603102903819272, S 12) --broadphase brute -t 1
    0x04bd87ff49d02f47ULL,  // random 6 (N 56, L 100, r 4.4603102903819272, S 12) --broadphase grid -t 1
    0x2025f0b245535550ULL,  // random 6 (N 56, L 100, r 4.4603102903819272, S 12) --substeps 2 -t 2
    0xb80a51a59bda15d7ULL,  // random 6 (N 56, L 100, r 4.4603102903819272, S 12) --engine exact
    0x63664993334372f6ULL,  // random 7 (N 1, L 250, r 39.894228040143268, S 6) --broadphase brute -t 1
    0x63664993334372f6ULL,  // random 7 (N 1, L 250, r 39.894228040143268, S 6) --broadphase grid -t 2
    0x63664993334372f6ULL,  // random 7 (N 1, L 250, r 39.894228040143268, S 6) --substeps 3 -t 2
    0x63664993334372f6ULL,  // random 7 (N 1, L 250, r 39.894228040143268, S 6) --engine exact
    0x6ecfa61f9bc3056fULL,  // random 8 (N 17, L 250, r 15.298738081941467, S 23) --broadphase brute -t 1
    0x6ecfa61f9bc3056fULL,  // random 8 (N 17, L 250, r 15.298738081941467, S 23) --broadphase grid -t 1
    0x1f3fe2a953123a36ULL,  // random 8 (N 17, L 250, r 15.298738081941467, S 23) --substeps 4 -t 2
    0xb3be4cfebbbfc884ULL,  // random 8 (N 17, L 250, r 15.298738081941467, S 23) --engine exact
    0xb9e10d7fd49c8cc4ULL,  // random 9 (N 52, L 250, r 11.571706841947286, S 20) --broadphase brute -t 1
    0xb9e10d7fd49c8cc4ULL,  // random 9 (N 52, L 250, r 11.571706841947286, S 20) --broadphase grid -t 2
    0x6177c594eb6281ceULL,  // random 9 (N 52, L 250, r 11.571706841947286, S 20) --substeps 2 -t 2
    0x75945a6c47d397c3ULL,  // random 9 (N 52, L 250, r 11.571706841947286, S 20) --engine exact
    0xb48d49fd593cb0c8ULL,  // random 10 (N 14, L 100, r 4.264872372458461, S 9) --broadphase brute -t 1
    0xb48d49fd593cb0c8ULL,  // random 10 (N 14, L 100, r 4.264872372458461, S 9) --broadphase grid -t 1
    0xd9556e3a2a278c95ULL,  // random 10 (N 14, L 100, r 4.264872372458461, S 9) --substeps 3 -t 2
    0xf0e429e5023de4b8ULL,  // random 10 (N 14, L 100, r 4.264872372458461, S 9) --engine exact
    0x16ee229670444396ULL,  // random 11 (N 6, L 250, r 34.06618254777608, S 22) --broadphase brute -t 1
    0x16ee229670444396ULL,  // random 11 (N 6, L 250, r 34.06618254777608, S 22) --broadphase grid -t 2
    0xc019d24af30021fdULL,  // random 11 (N 6, L 250, r 34.06618254777608, S 22) --substeps 4 -t 2
    0x8aeae87ac68c572bULL,  // random 11 (N 6, L 250, r 34.06618254777608, S 22) --engine exact
    0x15615b51cd046dc1ULL,  // random 12 (N 16, L 1000, r 39.894228040143268, S 10) --broadphase brute -t 1
    0x15615b51cd046dc1ULL,  // random 12 (N 16, L 1000, r 39.894228040143268, S 10) --broadphase grid -t 1
    0x14bf3e44e8d5d111ULL,  // random 12 (N 16, L 1000, r 39.894228040143268, S 10) --substeps 2 -t 2
    0xf7c62b4b26b6b3a3ULL,  // random 12 (N 16, L 1000, r 39.894228040143268, S 10) --engine exact
    0x6ff826d4c4660f8aULL,  // random 13 (N 8, L 100, r 5.6418958354775635, S 25) --broadphase brute -t 1
    0x6ff826d4c4660f8aULL,  // random 13 (N 8, L 100, r 5.6418958354775635, S 25) --broadphase grid -t 2
    0x426dc09986b70eb6ULL,  // random 13 (N 8, L 100, r 5.6418958354775635, S 25) --substeps 3 -t 2
    0xf05d9c1844c9f734ULL,  // random 13 (N 8, L 100, r 5.6418958354775635, S 25) --engine exact
    0x8aecccec6c8d7177ULL,  // random 14 (N 14, L 100, r 4.264872372458461, S 5) --broadphase brute -t 1
    0x8aecccec6c8d7177ULL,  // random 14 (N 14, L 100, r 4.264872372458461, S 5) --broadphase grid -t 1
    0x1e304fb81159bb00ULL,  // random 14 (N 14, L 100, r 4.264872372458461, S 5) --substeps 4 -t 2
    0x3a99be7d337735fbULL,  // random 14 (N 14, L 100, r 4.264872372458461, S 5) --engine exact
    0xf23f237c945f297bULL,  // random 15 (N 60, L 40, r 0.41202581549140227, S 12) --broadphase brute -t 1
    0xf23f237c945f297bULL,  // random 15 (N 60, L 40, r 0.41202581549140227, S 12) --broadphase grid -t 2
    0xd877b5880382027bULL,  // random 15 (N 60, L 40, r 0.41202581549140227, S 12) --substeps 2 -t 2
    0xae3438d5457484a9ULL,  // random 15 (N 60, L 40, r 0.41202581549140227, S 12) --engine exact
    0x18b0cb85da8e4098ULL,  // random 16 (N 52, L 100, r 0.5532334030530377, S 11) --broadphase brute -t 1
    0x18b0cb85da8e4098ULL,  // random 16 (N 52, L 100, r 0.5532334030530377, S 11) --broadphase grid -t 1
    0x3b34095f0ffc044bULL,  // random 16 (N 52, L 100, r 0.5532334030530377, S 11) --substeps 3 -t 2
    0x0ab8dd57a7f15f17ULL,  // random 16 (N 52, L 100, r 0.5532334030530377, S 11) --engine exact
    0x14e3f329c08047a8ULL,  // random 17 (N 14, L 1000, r 10.662180931146153, S 2) --broadphase brute -t 1
    0x14e3f329c08047a8ULL,  // random 17 (N 14, L 1000, r 10.662180931146153, S 2) --broadphase grid -t 2
    0x01fce982218cb53eULL,  // random 17 (N 14, L 1000, r 10.662180931146153, S 2) --substeps 4 -t 2
    0x7a6f906d1e2ae694ULL,  // random 17 (N 14, L 1000, r 10.662180931146153, S 2) --engine exact
    0xb072b70bac1ad93eULL,  // random 18 (N 7, L 100, r 9.536544540177923, S 8) --broadphase brute -t 1
    0xb072b70bac1ad93eULL,  // random 18 (N 7, L 100, r 9.536544540177923, S 8) --broadphase grid -t 1
    0x10792fc738617a48ULL,  // random 18 (N 7, L 100, r 9.536544540177923, S 8) --substeps 2 -t 2
    0x85886aa380640256ULL,  // random 18 (N 7, L 100, r 9.536544540177923, S 8) --engine exact
    0x8deafeabe547e92fULL,  // random 19 (N 22, L 40, r 1.3608764794580201, S 2) --broadphase brute -t 1
    0x8deafeabe547e92fULL,  // random 19 (N 22, L 40, r 1.3608764794580201, S 2) --broadphase grid -t 2
    0x2724c42219648022ULL,  // random 19 (N 22, L 40, r 1.3608764794580201, S 2) --substeps 3 -t 2
    0x780ed4471487bd1bULL,  // random 19 (N 22, L 40, r 1.3608764794580201, S 2) --engine exact
    0xdcfd2f7c216ec962ULL,  // random 20 (N 48, L 100, r 4.8176857377342568, S 10) --broadphase brute -t 1
    0xdcfd2f7c216ec962ULL,  // random 20 (N 48, L 100, r 4.8176857377342568, S 10) --broadphase grid -t 1
    0x819ee5a9de24fb6eULL,  // random 20 (N 48, L 100, r 4.8176857377342568, S 10) --substeps 4 -t 2
    0x2b9bae972d26026aULL,  // random 20 (N 48, L 100, r 4.8176857377342568, S 10) --engine exact
    0x4c97f8444316e536ULL,  // random 21 (N 31, L 100, r 4.5316797867100913, S 5) --broadphase brute -t 1
    0x4c97f8444316e536ULL,  // random 21 (N 31, L 100, r 4.5316797867100913, S 5) --broadphase grid -t 2
    0x6b31d495215358a4ULL,  // random 21 (N 31, L 100, r 4.5316797867100913, S 5) --substeps 2 -t 2
    0xaf986f257a47191cULL,  // random 21 (N 31, L 100, r 4.5316797867100913, S 5) --engine exact
    0xe31477726002cdccULL,  // random 22 (N 51, L 1000, r 11.172618598456882, S 18) --broadphase brute -t 1
    0xe31477726002cdccULL,  // random 22 (N 51, L 1000, r 11.172618598456882, S 18) --broadphase grid -t 1
    0xc661b131f5a4d42dULL,  // random 22 (N 51, L 1000, r 11.172618598456882, S 18) --substeps 3 -t 2
    0xc497bae9e19e7413ULL,  // random 22 (N 51, L 1000, r 11.172618598456882, S 18) --engine exact
    0x2cb541593a5cd959ULL,  // random 23 (N 55, L 1000, r 5.3793366115483616, S 19) --broadphase brute -t 1
    0x2cb541593a5cd959ULL,  // random 23 (N 55, L 1000, r 5.3793366115483616, S 19) --broadphase grid -t 2
    0x0c6346a519610730ULL,  // random 23 (N 55, L 1000, r 5.3793366115483616, S 19) --substeps 4 -t 2
    0xf818fde9c3cb8ffbULL,  // random 23 (N 55, L 1000, r 5.3793366115483616, S 19) --engine exact
    0x58bc5fbb51c70d5eULL,  // random 24 (N 40, L 250, r 9.9735570100358171, S 3) --broadphase brute -t 1
    0x58bc5fbb51c70d5eULL,  // random 24 (N 40, L 250, r 9.9735570100358171, S 3) --broadphase grid -t 1
    0x000ba56a993a89b3ULL,  // random 24 (N 40, L 250, r 9.9735570100358171, S 3) --substeps 2 -t 2
    0x57f45da0ad291dbcULL,  // random 24 (N 40, L 250, r 9.9735570100358171, S 3) --engine exact
    0xc03bf998ac537aa4ULL,  // random 25 (N 37, L 100, r 5.4872939267918959, S 15) --broadphase brute -t 1
    0xc03bf998ac537aa4ULL,  // random 25 (N 37, L 100, r 5.4872939267918959, S 15) --broadphase grid -t 2
    0x5d8a935341d29aa5ULL,  // random 25 (N 37, L 100, r 5.4872939267918959, S 15) --substeps 3 -t 2
    0xbbd20a9571a2f7fdULL,  // random 25 (N 37, L 100, r 5.4872939267918959, S 15) --engine exact
    0xa436ab3bea1ea18eULL,  // random 26 (N 9, L 100, r 1.329807601338109, S 16) --broadphase brute -t 1
    0xa436ab3bea1ea18eULL,  // random 26 (N 9, L 100, r 1.329807601338109, S 16) --broadphase grid -t 1
    0x6b79f0d7dd72169bULL,  // random 26 (N 9, L 100, r 1.329807601338109, S 16) --substeps 4 -t 2
    0x246d89b086c4ddd6ULL,  // random 26 (N 9, L 100, r 1.329807601338109, S 16) --engine exact
    0x8c043f1b70245124ULL,  // random 27 (N 4, L 100, r 7.9788456080286538, S 4) --broadphase brute -t 1
    0x8c043f1b70245124ULL,  // random 27 (N 4, L 100, r 7.9788456080286538, S 4) --broadphase grid -t 2
    0x2390ff0b8f0fffe3ULL,  // random 27 (N 4, L 100, r 7.9788456080286538, S 4) --substeps 2 -t 2
    0x2390ff0b8f0fffe3ULL,  // random 27 (N 4, L 100, r 7.9788456080286538, S 4) --engine exact
    0x3ae6295f48cc0b6dULL,  // random 28 (N 45, L 100, r 1.1894160774351807, S 1) --broadphase brute -t 1
    0x3ae6295f48cc0b6dULL,  // random 28 (N 45, L 100, r 1.1894160774351807, S 1) --broadphase grid -t 1
    0xbe553160696187f3ULL,  // random 28 (N 45, L 100, r 1.1894160774351807, S 1) --substeps 3 -t 2
    0xb5b3bf7f828b3333ULL,  // random 28 (N 45, L 100, r 1.1894160774351807, S 1) --engine exact
    0xe7f32815f9998c68ULL,  // random 29 (N 54, L 40, r 1.3734193849713408, S 8) --broadphase brute -t 1
    0xe7f32815f9998c68ULL,  // random 29 (N 54, L 40, r 1.3734193849713408, S 8) --broadphase grid -t 2
    0x9e8951adc9f4bd37ULL,  // random 29 (N 54, L 40, r 1.3734193849713408, S 8) --substeps 4 -t 2
    0xcddf191a1e874f02ULL,  // random 29 (N 54, L 40, r 1.3734193849713408, S 8) --engine exact
    0xc8cbded0e2fdbfd8ULL,  // random 30 (N 54, L 1000, r 5.4289167989213327, S 17) --broadphase brute -t 1
    0xc8cbded0e2fdbfd8ULL,  // random 30 (N 54, L 1000, r 5.4289167989213327, S 17) --broadphase grid -t 1
    0xfa74e144dea365a3ULL,  // random 30 (N 54, L 1000, r 5.4289167989213327, S 17) --substeps 2 -t 2
    0x0d3fdacee6ba796cULL,  // random 30 (N 54, L 1000, r 5.4289167989213327, S 17) --engine exact
    0xdc13d0e4aeb6fdc8ULL,  // random 31 (N 18, L 100, r 3.7612638903183755, S 22) --broadphase brute -t 1
    0xdc13d0e4aeb6fdc8ULL,  // random 31 (N 18, L 100, r 3.7612638903183755, S 22) --broadphase grid -t 2
    0x3ddfaaaa16e38712ULL,  // random 31 (N 18, L 100, r 3.7612638903183755, S 22) --substeps 3 -t 2
    0x63e4c04732a2a752ULL,  // random 31 (N 18, L 100, r 3.7612638903183755, S 22) --engine exact
    0x998852fe5e657156ULL,  // random 32 (N 52, L 40, r 0.44258672244243014, S 8) --broadphase brute -t 1
    0x998852fe5e657156ULL,  // random 32 (N 52, L 40, r 0.44258672244243014, S 8) --broadphase grid -t 1
    0x1f8546f6979d2201ULL,  // random 32 (N 52, L 40, r 0.44258672244243014, S 8) --substeps 4 -t 2
    0x94683a7ef7b18165ULL,  // random 32 (N 52, L 40, r 0.44258672244243014, S 8) --engine exact
    0xbcbc521382080759ULL,  // random 33 (N 23, L 1000, r 8.3185215840497957, S 21) --broadphase brute -t 1
    0xbcbc521382080759ULL,  // random 33 (N 23, L 1000, r 8.3185215840497957, S 21) --broadphase grid -t 2
    0x8b1bb4c18b78f824ULL,  // random 33 (N 23, L 1000, r 8.3185215840497957, S 21) --substeps 2 -t 2
    0x6cd8d8199567c9b1ULL,  // random 33 (N 23, L 1000, r 8.3185215840497957, S 21) --engine exact
    0xd72e23b3af92110dULL,  // random 34 (N 16, L 250, r 2.4933892525089543, S 14) --broadphase brute -t 1
    0xd72e23b3af92110dULL,  // random 34 (N 16, L 250, r 2.4933892525089543, S 14) --broadphase grid -t 1
    0x0f6b5e2b4c43edd4ULL,  // random 34 (N 16, L 250, r 2.4933892525089543, S 14) --substeps 3 -t 2
    0x62ab5fb3301bfe47ULL,  // random 34 (N 16, L 250, r 2.4933892525089543, S 14) --engine exact
    0x4a5897cfa98fbea4ULL,  // random 35 (N 58, L 1000, r 33.130353109882257, S 19) --broadphase brute -t 1
    0x4a5897cfa98fbea4ULL,  // random 35 (N 58, L 1000, r 33.130353109882257, S 19) --broadphase grid -t 2
    0x421880c40c514e23ULL,  // random 35 (N 58, L 1000, r 33.130353109882257, S 19) --substeps 4 -t 2
    0xbb6a2285a1a31290ULL,  // random 35 (N 58, L 1000, r 33.130353109882257, S 19) --engine exact
    0x612be00bd0fc48b5ULL,  // random 36 (N 33, L 250, r 3.4723468516951068, S 16) --broadphase brute -t 1
    0x612be00bd0fc48b5ULL,  // random 36 (N 33, L 250, r 3.4723468516951068, S 16) --broadphase grid -t 1
    0x7af85bd1e974972bULL,  // random 36 (N 33, L 250, r 3.4723468516951068, S 16) --substeps 2 -t 2
    0x8890434746e2fd9eULL,  // random 36 (N 33, L 250, r 3.4723468516951068, S 16) --engine exact
    0x3502d3b4a91d5069ULL,  // random 37 (N 51, L 40, r 0.22345237196913764, S 5) --broadphase brute -t 1
    0x3502d3b4a91d5069ULL,  // random 37 (N 51, L 40, r 0.22345237196913764, S 5) --broadphase grid -t 2
    0x546755f92072ae57ULL,  // random 37 (N 51, L 40, r 0.22345237196913764, S 5) --substeps 3 -t 2
    0x692584515c1e8de0ULL,  // random 37 (N 51, L 40, r 0.22345237196913764, S 5) --engine exact
    0xdbc83fd077ca42deULL,  // random 38 (N 5, L 100, r 3.5682482323055424, S 24) --broadphase brute -t 1
    0xdbc83fd077ca42deULL,  // random 38 (N 5, L 100, r 3.5682482323055424, S 24) --broadphase grid -t 1
    0x38a288a3fa958be8ULL,  // random 38 (N 5, L 100, r 3.5682482323055424, S 24) --substeps 4 -t 2
    0x294655259e21e6f2ULL,  // random 38 (N 5, L 100, r 3.5682482323055424, S 24) --engine exact
    0x902a915b85ce1542ULL,  // random 39 (N 13, L 40, r 2.79916421013368, S 10) --broadphase brute -t 1
    0x902a915b85ce1542ULL,  // random 39 (N 13, L 40, r 2.79916421013368, S 10) --broadphase grid -t 2
    0x74dd70776ade7317ULL,  // random 39 (N 13, L 40, r 2.79916421013368, S 10) --substeps 2 -t 2
    0xe365e1f0ac472486ULL,  // random 39 (N 13, L 40, r 2.79916421013368, S 10) --engine exact
    0x5902a88cb5d7b654ULL,  // random 40 (N 57, L 100, r 1.0568239179860266, S 18) --broadphase brute -t 1
    0x5902a88cb5d7b654ULL,  // random 40 (N 57, L 100, r 1.0568239179860266, S 18) --broadphase grid -t 1
    0xb5ae576f414c25f9ULL,  // random 40 (N 57, L 100, r 1.0568239179860266, S 18) --substeps 3 -t 2
    0xfcdf0cc4e5114792ULL,  // random 40 (N 57, L 100, r 1.0568239179860266, S 18) --engine exact
    0x9a6b3de25e27c79bULL,  // random 41 (N 42, L 250, r 3.0779065153728635, S 5) --broadphase brute -t 1
    0x9a6b3de25e27c79bULL,  // random 41 (N 42, L 250, r 3.0779065153728635, S 5) --broadphase grid -t 2
    0xe0dbc150997d3956ULL,  // random 41 (N 42, L 250, r 3.0779065153728635, S 5) --substeps 4 -t 2
    0xbea1c8702a670c10ULL,  // random 41 (N 42, L 250, r 3.0779065153728635, S 5) --engine exact
    0x2874532605761c32ULL,  // random 42 (N 59, L 250, r 1.2984465257417248, S 25) --broadphase brute -t 1
    0x2874532605761c32ULL,  // random 42 (N 59, L 250, r 1.2984465257417248, S 25) --broadphase grid -t 1
    0xbb8edd5d3b3a77b6ULL,  // random 42 (N 59, L 250, r 1.2984465257417248, S 25) --substeps 2 -t 2
    0xe6b786fba2056140ULL,  // random 42 (N 59, L 250, r 1.2984465257417248, S 25) --engine exact
    0x168bf7510874c6b4ULL,  // random 43 (N 58, L 1000, r 10.476737551287066, S 7) --broadphase brute -t 1
    0x168bf7510874c6b4ULL,  // random 43 (N 58, L 1000, r 10.476737551287066, S 7) --broadphase grid -t 2
    0x4ec7a60fc38cf64fULL,  // random 43 (N 58, L 1000, r 10.476737551287066, S 7) --substeps 3 -t 2
    0x891f678bc04ffcd9ULL,  // random 43 (N 58, L 1000, r 10.476737551287066, S 7) --engine exact
    0x33732953ea086603ULL,  // random 44 (N 11, L 100, r 7.6075307926218239, S 9) --broadphase brute -t 1
    0x33732953ea086603ULL,  // random 44 (N 11, L 100, r 7.6075307926218239, S 9) --broadphase grid -t 1
    0xb16b965733ffb135ULL,  // random 44 (N 11, L 100, r 7.6075307926218239, S 9) --substeps 4 -t 2
    0x3778bd7297f7cbcfULL,  // random 44 (N 11, L 100, r 7.6075307926218239, S 9) --engine exact
    0xd94ee49173026b6bULL,  // random 45 (N 56, L 40, r 1.3486710626894709, S 7) --broadphase brute -t 1
    0xd94ee49173026b6bULL,  // random 45 (N 56, L 40, r 1.3486710626894709, S 7) --broadphase grid -t 2
    0x56974d68cf458a4fULL,  // random 45 (N 56, L 40, r 1.3486710626894709, S 7) --substeps 2 -t 2
    0x3c84080ea0159aabULL,  // random 45 (N 56, L 40, r 1.3486710626894709, S 7) --engine exact
    0x631bcda3a3485891ULL,  // random 46 (N 16, L 1000, r 83.444764726556826, S 6) --broadphase brute -t 1
    0x631bcda3a3485891ULL,  // random 46 (N 16, L 1000, r 83.444764726556826, S 6) --broadphase grid -t 1
    0x4b033d466d6e02cfULL,  // random 46 (N 16, L 1000, r 83.444764726556826, S 6) --substeps 3 -t 2
    0x006178fd7c6058c3ULL,  // random 46 (N 16, L 1000, r 83.444764726556826, S 6) --engine exact
    0xf58f67a7195e6befULL,  // random 47 (N 49, L 100, r 2.2796701737224723, S 8) --broadphase brute -t 1
    0xf58f67a7195e6befULL,  // random 47 (N 49, L 100, r 2.2796701737224723, S 8) --broadphase grid -t 2
    0x2a3830eef85b0457ULL,  // random 47 (N 49, L 100, r 2.2796701737224723, S 8) --substeps 4 -t 2
    0x67ebae06e3a89c00ULL,  // random 47 (N 49, L 100, r 2.2796701737224723, S 8) --engine exact
    0xcc2039b1192d6250ULL,  // random 48 (N 45, L 100, r 4.9756844345348714, S 20) --broadphase brute -t 1
    0xcc2039b1192d6250ULL,  // random 48 (N 45, L 100, r 4.9756844345348714, S 20) --broadphase grid -t 1
    0xb44f55b2700ed7b4ULL,  // random 48 (N 45, L 100, r 4.9756844345348714, S 20) --substeps 2 -t 2
    0xf06e289e900ca793ULL,  // random 48 (N 45, L 100, r 4.9756844345348714, S 20) --engine exact
    0x135703f619acb4beULL,  // random 49 (N 57, L 100, r 2.1136478359720532, S 4) --broadphase brute -t 1
    0x135703f619acb4beULL,  // random 49 (N 57, L 100, r 2.1136478359720532, S 4) --broadphase grid -t 2
    0x43011cdb50357a36ULL,  // random 49 (N 57, L 100, r 2.1136478359720532, S 4) --substeps 3 -t 2
    0x19a3a821f2e03ae4ULL,  // random 49 (N 57, L 100, r 2.1136478359720532, S 4) --engine exact
    0x3f749194b7bc5ee1ULL,  // random 50 (N 31, L 40, r 1.8126719146840364, S 14) --broadphase brute -t 1
    0x3f749194b7bc5ee1ULL,  // random 50 (N 31, L 40, r 1.8126719146840364, S 14) --broadphase grid -t 1
    0x46983b192fa4462cULL,  // random 50 (N 31, L 40, r 1.8126719146840364, S 14) --substeps 4 -t 2
    0x6e08a49f0d9a8fccULL,  // random 50 (N 31, L 40, r 1.8126719146840364, S 14) --engine exact
    0xcfe294e24ca371dcULL,  // random 51 (N 14, L 100, r 8.9206205807638543, S 1) --broadphase brute -t 1
    0xcfe294e24ca371dcULL,  // random 51 (N 14, L 100, r 8.9206205807638543, S 1) --broadphase grid -t 2
    0x1fa598f20b2b343eULL,  // random 51 (N 14, L 100, r 8.9206205807638543, S 1) --substeps 2 -t 2
    0xe64db6a3a1576bdcULL,  // random 51 (N 14, L 100, r 8.9206205807638543, S 1) --engine exact
    0x5497e98a711fb06eULL,  // random 52 (N 60, L 100, r 4.3090691215220085, S 14) --broadphase brute -t 1
    0x5497e98a711fb06eULL,  // random 52 (N 60, L 100, r 4.3090691215220085, S 14) --broadphase grid -t 1
    0x83b48030fea197e8ULL,  // random 52 (N 60, L 100, r 4.3090691215220085, S 14) --substeps 3 -t 2
    0x24fac3a87c16463eULL,  // random 52 (N 60, L 100, r 4.3090691215220085, S 14) --engine exact
    0xae0223187785f0fbULL,  // random 53 (N 14, L 250, r 5.3310904655730766, S 13) --broadphase brute -t 1
    0xae0223187785f0fbULL,  // random 53 (N 14, L 250, r 5.3310904655730766, S 13) --broadphase grid -t 2
    0x54626c3ec01e865dULL,  // random 53 (N 14, L 250, r 5.3310904655730766, S 13) --substeps 4 -t 2
    0xa17eca75cfa95026ULL,  // random 53 (N 14, L 250, r 5.3310904655730766, S 13) --engine exact
    0xda2055382ffc12b4ULL,  // random 54 (N 31, L 250, r 11.329199466775227, S 23) --broadphase brute -t 1
    0xda2055382ffc12b4ULL,  // random 54 (N 31, L 250, r 11.329199466775227, S 23) --broadphase grid -t 1
    0x5ad69ff268103eefULL,  // random 54 (N 31, L 250, r 11.329199466775227, S 23) --substeps 2 -t 2
    0x56f9ac07241e3e0fULL,  // random 54 (N 31, L 250, r 11.329199466775227, S 23) --engine exact
    0x579c7346b79650acULL,  // random 55 (N 60, L 1000, r 32.573500793527998, S 19) --broadphase brute -t 1
    0x579c7346b79650acULL,  // random 55 (N 60, L 1000, r 32.573500793527998, S 19) --broadphase grid -t 2
    0x640e8d1f5a237ad8ULL,  // random 55 (N 60, L 1000, r 32.573500793527998, S 19) --substeps 3 -t 2
    0x3e26ce810a3a169fULL,  // random 55 (N 60, L 1000, r 32.573500793527998, S 19) --engine exact
    0xe22c697c512541b6ULL,  // random 56 (N 39, L 100, r 0.6388189083547281, S 15) --broadphase brute -t 1
    0xe22c697c512541b6ULL,  // random 56 (N 39, L 100, r 0.6388189083547281, S 15) --broadphase grid -t 1
    0x3d0f5afd30c55ca6ULL,  // random 56 (N 39, L 100, r 0.6388189083547281, S 15) --substeps 4 -t 2
    0x9bf81bcba3b8b7ddULL,  // random 56 (N 39, L 100, r 0.6388189083547281, S 15) --engine exact
    0x03a28eb49af85242ULL,  // random 57 (N 48, L 40, r 0.46065886596178063, S 13) --broadphase brute -t 1
    0x03a28eb49af85242ULL,  // random 57 (N 48, L 40, r 0.46065886596178063, S 13) --broadphase grid -t 2
    0x12afa32f9832fb17ULL,  // random 57 (N 48, L 40, r 0.46065886596178063, S 13) --substeps 2 -t 2
    0x6d883991b2f8e215ULL,  // random 57 (N 48, L 40, r 0.46065886596178063, S 13) --engine exact
    0xd347aab579745608ULL,  // random 58 (N 30, L 40, r 1.8426354638471225, S 3) --broadphase brute -t 1
    0xd347aab579745608ULL,  // random 58 (N 30, L 40, r 1.8426354638471225, S 3) --broadphase grid -t 1
    0x7d465a203ad0ce6aULL,  // random 58 (N 30, L 40, r 1.8426354638471225, S 3) --substeps 3 -t 2
    0x94e5ead8f831b7faULL,  // random 58 (N 30, L 40, r 1.8426354638471225, S 3) --engine exact
    0x7d212024cfcdc557ULL,  // random 59 (N 29, L 250, r 15.495303805002495, S 22) --broadphase brute -t 1
    0x7d212024cfcdc557ULL,  // random 59 (N 29, L 250, r 15.495303805002495, S 22) --broadphase grid -t 2
    0xbb661e59d8db7b64ULL,  // random 59 (N 29, L 250, r 15.495303805002495, S 22) --substeps 4 -t 2
    0xe7d629dd06068e94ULL,  // random 59 (N 29, L 250, r 15.495303805002495, S 22) --engine exact
    0x4bd751af1809f5feULL,  // random 60 (N 60, L 250, r 1.2875806734106321, S 3) --broadphase brute -t 1
    0x4bd751af1809f5feULL,  // random 60 (N 60, L 250, r 1.2875806734106321, S 3) --broadphase grid -t 1
    0xa75f164cd2ddcc6dULL,  // random 60 (N 60, L 250, r 1.2875806734106321, S 3) --substeps 2 -t 2
    0x0f999bc6104b9ba1ULL,  // random 60 (N 60, L 250, r 1.2875806734106321, S 3) --engine exact
    0x89222525018a3986ULL,  // random 61 (N 30, L 100, r 0.72836562039471942, S 19) --broadphase brute -t 1
    0x89222525018a3986ULL,  // random 61 (N 30, L 100, r 0.72836562039471942, S 19) --broadphase grid -t 2
    0x0ae5152921239f85ULL,  // random 61 (N 30, L 100, r 0.72836562039471942, S 19) --substeps 3 -t 2
    0x6a909e1d1d193f89ULL,  // random 61 (N 30, L 100, r 0.72836562039471942, S 19) --engine exact
    0x9fb2da0e3c1e520eULL,  // random 62 (N 45, L 250, r 12.439211086337179, S 4) --broadphase brute -t 1
    0x9fb2da0e3c1e520eULL,  // random 62 (N 45, L 250, r 12.439211086337179, S 4) --broadphase grid -t 1
    0xd036eec3766ff51dULL,  // random 62 (N 45, L 250, r 12.439211086337179, S 4) --substeps 4 -t 2
    0xb3057657954b01aeULL,  // random 62 (N 45, L 250, r 12.439211086337179, S 4) --engine exact
    0xa22de85d06ecc71aULL,  // random 63 (N 37, L 250, r 13.71823481697974, S 23) --broadphase brute -t 1
    0xa22de85d06ecc71aULL,  // random 63 (N 37, L 250, r 13.71823481697974, S 23) --broadphase grid -t 2
    0x763eb45bfda1784aULL,  // random 63 (N 37, L 250, r 13.71823481697974, S 23) --substeps 2 -t 2
    0x4580907049ec40b4ULL,  // random 63 (N 37, L 250, r 13.71823481697974, S 23) --engine exact
    0x928f3521d3b9fe7aULL,  // random 64 (N 16, L 100, r 6.3078313050504002, S 1) --broadphase brute -t 1
    0x928f3521d3b9fe7aULL,  // random 64 (N 16, L 100, r 6.3078313050504002, S 1) --broadphase grid -t 1
    0x12cfe0ad5daba50eULL,  // random 64 (N 16, L 100, r 6.3078313050504002, S 1) --substeps 3 -t 2
    0x7578cfd9450eeb81ULL,  // random 64 (N 16, L 100, r 6.3078313050504002, S 1) --engine exact
    0xd4ce69c081a8f893ULL,  // random 65 (N 4, L 100, r 7.9788456080286538, S 24) --broadphase brute -t 1
    0xd4ce69c081a8f893ULL,  // random 65 (N 4, L 100, r 7.9788456080286538, S 24) --broadphase grid -t 2
    0x73179899974de0f0ULL,  // random 65 (N 4, L 100, r 7.9788456080286538, S 24) --substeps 4 -t 2
    0xfc657842242c581cULL,  // random 65 (N 4, L 100, r 7.9788456080286538, S 24) --engine exact
    0x68c58eafb5f310c1ULL,  // random 66 (N 10, L 40, r 3.1915382432114612, S 22) --broadphase brute -t 1
    0x68c58eafb5f310c1ULL,  // random 66 (N 10, L 40, r 3.1915382432114612, S 22) --broadphase grid -t 1
    0xa13783513caa35b4ULL,  // random 66 (N 10, L 40, r 3.1915382432114612, S 22) --substeps 2 -t 2
    0xffde3efafabf3d69ULL,  // random 66 (N 10, L 40, r 3.1915382432114612, S 22) --engine exact
    0x933be8fb0af0d4bbULL,  // random 67 (N 24, L 250, r 2.0358437995954999, S 8) --broadphase brute -t 1
    0x933be8fb0af0d4bbULL,  // random 67 (N 24, L 250, r 2.0358437995954999, S 8) --broadphase grid -t 2
    0x4478f3fa9e84b919ULL,  // random 67 (N 24, L 250, r 2.0358437995954999, S 8) --substeps 3 -t 2
    0x0e21260523d6ae44ULL,  // random 67 (N 24, L 250, r 2.0358437995954999, S 8) --engine exact
    0xbaee519888d499b1ULL,  // random 68 (N 49, L 250, r 5.6991754343061816, S 24) --broadphase brute -t 1
    0xbaee519888d499b1ULL,  // random 68 (N 49, L 250, r 5.6991754343061816, S 24) --broadphase grid -t 1
    0x0ec61d6f270dcf0aULL,  // random 68 (N 49, L 250, r 5.6991754343061816, S 24) --substeps 4 -t 2
    0xa50aef53600b8fabULL,  // random 68 (N 49, L 250, r 5.6991754343061816, S 24) --engine exact
    0x136d338b66f3eb04ULL,  // random 69 (N 59, L 250, r 1.2984465257417248, S 11) --broadphase brute -t 1
    0x136d338b66f3eb04ULL,  // random 69 (N 59, L 250, r 1.2984465257417248, S 11) --broadphase grid -t 2
    0xfcef5834e71ad2cbULL,  // random 69 (N 59, L 250, r 1.2984465257417248, S 11) --substeps 2 -t 2
    0x04ed756bde50dfc4ULL,  // random 69 (N 59, L 250, r 1.2984465257417248, S 11) --engine exact
    0x21acd278553a2d39ULL,  // random 70 (N 51, L 40, r 0.44690474393827528, S 1) --broadphase brute -t 1
    0x21acd278553a2d39ULL,  // random 70 (N 51, L 40, r 0.44690474393827528, S 1) --broadphase grid -t 1
    0xe4e931e3e914f454ULL,  // random 70 (N 51, L 40, r 0.44690474393827528, S 1) --substeps 3 -t 2
    0x3e5a9a491dc81ad9ULL,  // random 70 (N 51, L 40, r 0.44690474393827528, S 1) --engine exact
    0x104c4ef5ebbd8dfcULL,  // random 71 (N 2, L 1000, r 28.209479177387816, S 4) --broadphase brute -t 1
    0x104c4ef5ebbd8dfcULL,  // random 71 (N 2, L 1000, r 28.209479177387816, S 4) --broadphase grid -t 2
    0x3ceff13d22af1accULL,  // random 71 (N 2, L 1000, r 28.209479177387816, S 4) --substeps 4 -t 2
    0x3ceff13d22af1accULL,  // random 71 (N 2, L 1000, r 28.209479177387816, S 4) --engine exact
    0x43e76d34e74e99bfULL,  // random 72 (N 29, L 40, r 0.59265377337814629, S 9) --broadphase brute -t 1
    0x43e76d34e74e99bfULL,  // random 72 (N 29, L 40, r 0.59265377337814629, S 9) --broadphase grid -t 1
    0x904d6fa2541b0594ULL,  // random 72 (N 29, L 40, r 0.59265377337814629, S 9) --substeps 2 -t 2
    0xb0a8b25b29fb5f01ULL,  // random 72 (N 29, L 40, r 0.59265377337814629, S 9) --engine exact
    0xf516c041e79ef843ULL,  // random 73 (N 52, L 100, r 1.1064668061060754, S 14) --broadphase brute -t 1
    0xf516c041e79ef843ULL,  // random 73 (N 52, L 100, r 1.1064668061060754, S 14) --broadphase grid -t 2
    0xd733444a4d224ad0ULL,  // random 73 (N 52, L 100, r 1.1064668061060754, S 14) --substeps 3 -t 2
    0xf16af82a2c849b88ULL,  // random 73 (N 52, L 100, r 1.1064668061060754, S 14) --engine exact
    0xf06bc009b52a177cULL,  // random 74 (N 19, L 250, r 4.5761818015145055, S 9) --broadphase brute -t 1
    0xf06bc009b52a177cULL,  // random 74 (N 19, L 250, r 4.5761818015145055, S 9) --broadphase grid -t 1
    0xeb834ef2dd1d2dbeULL,  // random 74 (N 19, L 250, r 4.5761818015145055, S 9) --substeps 4 -t 2
    0xa29a46d24e2259dbULL,  // random 74 (N 19, L 250, r 4.5761818015145055, S 9) --engine exact
    0x384d3431f95dccd2ULL,  // random 75 (N 28, L 1000, r 63.078313050504001, S 24) --broadphase brute -t 1
    0x384d3431f95dccd2ULL,  // random 75 (N 28, L 1000, r 63.078313050504001, S 24) --broadphase grid -t 2
    0x877bb94088131747ULL,  // random 75 (N 28, L 1000, r 63.078313050504001, S 24) --substeps 2 -t 2
    0xd76c2d1296922195ULL,  // random 75 (N 28, L 1000, r 63.078313050504001, S 24) --engine exact
    0x14c127aff8f85dadULL,  // random 76 (N 44, L 100, r 3.8037653963109119, S 14) --broadphase brute -t 1
    0x14c127aff8f85dadULL,  // random 76 (N 44, L 100, r 3.8037653963109119, S 14) --broadphase grid -t 1
    0xf8303d265b9f75bbULL,  // random 76 (N 44, L 100, r 3.8037653963109119, S 14) --substeps 3 -t 2
    0xb09ab6d91eab84b5ULL,  // random 76 (N 44, L 100, r 3.8037653963109119, S 14) --engine exact
    0x7151d86b45b0eaf5ULL,  // random 77 (N 22, L 100, r 0.8505477996612627, S 5) --broadphase brute -t 1
    0x7151d86b45b0eaf5ULL,  // random 77 (N 22, L 100, r 0.8505477996612627, S 5) --broadphase grid -t 2
    0xe9ffb52bc6b9c319ULL,  // random 77 (N 22, L 100, r 0.8505477996612627, S 5) --substeps 4 -t 2
    0xa84aaa0690cc493fULL,  // random 77 (N 22, L 100, r 0.8505477996612627, S 5) --engine exact
    0x60eece80f53c95beULL,  // random 78 (N 27, L 40, r 0.61421182128237428, S 20) --broadphase brute -t 1
    0x60eece80f53c95beULL,  // random 78 (N 27, L 40, r 0.61421182128237428, S 20) --broadphase grid -t 1
    0x5379f9c433c6f7aeULL,  // random 78 (N 27, L 40, r 0.61421182128237428, S 20) --substeps 2 -t 2
    0xcbe64bc6745d36ceULL,  // random 78 (N 27, L 40, r 0.61421182128237428, S 20) --engine exact
    0xb3dec42fcf95120dULL,  // random 79 (N 18, L 250, r 19.66811966422145, S 25) --broadphase brute -t 1
    0xb3dec42fcf95120dULL,  // random 79 (N 18, L 250, r 19.66811966422145, S 25) --broadphase grid -t 2
    0x6beed88fddc49fbcULL,  // random 79 (N 18, L 250, r 19.66811966422145, S 25) --substeps 3 -t 2
    0x1abeb622abebd855ULL,  // random 79 (N 18, L 250, r 19.66811966422145, S 25) --engine exact
    0x4d7dd90225b66c17ULL,  // random 80 (N 31, L 100, r 1.4330429752549927, S 8) --broadphase brute -t 1
    0x4d7dd90225b66c17ULL,  // random 80 (N 31, L 100, r 1.4330429752549927, S 8) --broadphase grid -t 1
    0x41681e64a8bf3a91ULL,  // random 80 (N 31, L 100, r 1.4330429752549927, S 8) --substeps 4 -t 2
    0x8bca776f96d67ecaULL,  // random 80 (N 31, L 100, r 1.4330429752549927, S 8) --engine exact
    0xab02d063de7f582fULL,  // random 81 (N 35, L 250, r 1.6858388283618386, S 19) --broadphase brute -t 1
    0xab02d063de7f582fULL,  // random 81 (N 35, L 250, r 1.6858388283618386, S 19) --broadphase grid -t 2
    0x6fb7b0a64441c475ULL,  // random 81 (N 35, L 250, r 1.6858388283618386, S 19) --substeps 2 -t 2
    0x43618ad25d307273ULL,  // random 81 (N 35, L 250, r 1.6858388283618386, S 19) --engine exact
    0xe356f7dc6428d88fULL,  // random 82 (N 37, L 1000, r 6.5585706891285422, S 13) --broadphase brute -t 1
    0xe356f7dc6428d88fULL,  // random 82 (N 37, L 1000, r 6.5585706891285422, S 13) --broadphase grid -t 1
    0xc298ba9a556dbe47ULL,  // random 82 (N 37, L 1000, r 6.5585706891285422, S 13) --substeps 3 -t 2
    0x06935ceadbabd668ULL,  // random 82 (N 37, L 1000, r 6.5585706891285422, S 13) --engine exact
    0x53dfa5ad9e148192ULL,  // random 83 (N 53, L 1000, r 45.848079765622074, S 1) --broadphase brute -t 1
    0x53dfa5ad9e148192ULL,  // random 83 (N 53, L 1000, r 45.848079765622074, S 1) --broadphase grid -t 2
    0xff69e98ddf4ac68fULL,  // random 83 (N 53, L 1000, r 45.848079765622074, S 1) --substeps 4 -t 2
    0x68bf6f0c29cf13a8ULL,  // random 83 (N 53, L 1000, r 45.848079765622074, S 1) --engine exact
    0xee5346e1776297acULL,  // random 84 (N 38, L 250, r 6.4716983675867565, S 6) --broadphase brute -t 1
    0xee5346e1776297acULL,  // random 84 (N 38, L 250, r 6.4716983675867565, S 6) --broadphase grid -t 1
    0xa38ef737d20efb37ULL,  // random 84 (N 38, L 250, r 6.4716983675867565, S 6) --substeps 2 -t 2
    0xe0bcb8de31e3dca2ULL,  // random 84 (N 38, L 250, r 6.4716983675867565, S 6) --engine exact
    0x18c25314e0fe245fULL,  // random 85 (N 9, L 40, r 2.1276921621409746, S 7) --broadphase brute -t 1
    0x18c25314e0fe245fULL,  // random 85 (N 9, L 40, r 2.1276921621409746, S 7) --broadphase grid -t 2
    0xcb8213077090f4c8ULL,  // random 85 (N 9, L 40, r 2.1276921621409746, S 7) --substeps 3 -t 2
    0xa34eafbfd0f6c3acULL,  // random 85 (N 9, L 40, r 2.1276921621409746, S 7) --engine exact
    0x8dc274bb3dead0c6ULL,  // random 86 (N 12, L 40, r 0.92131773192356126, S 22) --broadphase brute -t 1
    0x8dc274bb3dead0c6ULL,  // random 86 (N 12, L 40, r 0.92131773192356126, S 22) --broadphase grid -t 1
    0x2e3042c7c7daece4ULL,  // random 86 (N 12, L 40, r 0.92131773192356126, S 22) --substeps 4 -t 2
    0x15e3707eb86d8129ULL,  // random 86 (N 12, L 40, r 0.92131773192356126, S 22) --engine exact
    0x520e3190100395a3ULL,  // random 87 (N 55, L 250, r 1.3448341528870904, S 22) --broadphase brute -t 1
    0x520e3190100395a3ULL,  // random 87 (N 55, L 250, r 1.3448341528870904, S 22) --broadphase grid -t 2
    0x0401a2aa79969b65ULL,  // random 87 (N 55, L 250, r 1.3448341528870904, S 22) --substeps 2 -t 2
    0x99cd98540d12fb55ULL,  // random 87 (N 55, L 250, r 1.3448341528870904, S 22) --engine exact
    0x8000533c56af86eaULL,  // random 88 (N 20, L 40, r 2.2567583341910251, S 17) --broadphase brute -t 1
    0x8000533c56af86eaULL,  // random 88 (N 20, L 40, r 2.2567583341910251, S 17) --broadphase grid -t 1
    0xae6a2bfd610ea51aULL,  // random 88 (N 20, L 40, r 2.2567583341910251, S 17) --substeps 3 -t 2
    0xdd10b4d455b7cd3dULL,  // random 88 (N 20, L 40, r 2.2567583341910251, S 17) --engine exact
    0xcc8fbdfa1610918eULL,  // random 89 (N 45, L 100, r 3.7612638903183755, S 21) --broadphase brute -t 1
    0xcc8fbdfa1610918eULL,  // random 89 (N 45, L 100, r 3.7612638903183755, S 21) --broadphase grid -t 2
    0xd94dde6f103d2afdULL,  // random 89 (N 45, L 100, r 3.7612638903183755, S 21) --substeps 4 -t 2
    0x97fa0075992788eeULL,  // random 89 (N 45, L 100, r 3.7612638903183755, S 21) --engine exact
    0x4f8b146cdc47a529ULL,  // random 90 (N 49, L 100, r 1.1398350868612361, S 21) --broadphase brute -t 1
    0x4f8b146cdc47a529ULL,  // random 90 (N 49, L 100, r 1.1398350868612361, S 21) --broadphase grid -t 1
    0xbdab1f9106701e37ULL,  // random 90 (N 49, L 100, r 1.1398350868612361, S 21) --substeps 2 -t 2
    0xfadfb5b0353a2ef7ULL,  // random 90 (N 49, L 100, r 1.1398350868612361, S 21) --engine exact
    0x378905e0545d3db3ULL,  // random 91 (N 41, L 100, r 5.2127531269024159, S 25) --broadphase brute -t 1
    0x378905e0545d3db3ULL,  // random 91 (N 41, L 100, r 5.2127531269024159, S 25) --broadphase grid -t 2
    0xd6e779c35b42dd2fULL,  // random 91 (N 41, L 100, r 5.2127531269024159, S 25) --substeps 3 -t 2
    0xe8d5e31cba26ce42ULL,  // random 91 (N 41, L 100, r 5.2127531269024159, S 25) --engine exact
    0x38ef0791f3d24c47ULL,  // random 92 (N 9, L 250, r 13.29807601338109, S 11) --broadphase brute -t 1
    0x38ef0791f3d24c47ULL,  // random 92 (N 9, L 250, r 13.29807601338109, S 11) --broadphase grid -t 1
    0x42dd980cf183536aULL,  // random 92 (N 9, L 250, r 13.29807601338109, S 11) --substeps 4 -t 2
    0x42dd980cf183536aULL,  // random 92 (N 9, L 250, r 13.29807601338109, S 11) --engine exact
    0xb263044b8ab79e0fULL,  // random 93 (N 45, L 250, r 1.4867700967939759, S 5) --broadphase brute -t 1
    0xb263044b8ab79e0fULL,  // random 93 (N 45, L 250, r 1.4867700967939759, S 5) --broadphase grid -t 2
    0x0e93e99b13695374ULL,  // random 93 (N 45, L 250, r 1.4867700967939759, S 5) --substeps 2 -t 2
    0xf91c8354fce8bde8ULL,  // random 93 (N 45, L 250, r 1.4867700967939759, S 5) --engine exact
    0xc0e90c770e3f4a71ULL,  // random 94 (N 8, L 1000, r 28.209479177387816, S 15) --broadphase brute -t 1
    0xc0e90c770e3f4a71ULL,  // random 94 (N 8, L 1000, r 28.209479177387816, S 15) --broadphase grid -t 1
    0x70693dc59c41cfd6ULL,  // random 94 (N 8, L 1000, r 28.209479177387816, S 15) --substeps 3 -t 2
    0x6869a3c5ca12a6b3ULL,  // random 94 (N 8, L 1000, r 28.209479177387816, S 15) --engine exact
    0xbc55b99867d214dcULL,  // random 95 (N 14, L 1000, r 89.206205807638554, S 8) --broadphase brute -t 1
    0xbc55b99867d214dcULL,  // random 95 (N 14, L 1000, r 89.206205807638554, S 8) --broadphase grid -t 2
    0xb022bed51b81a772ULL,  // random 95 (N 14, L 1000, r 89.206205807638554, S 8) --substeps 4 -t 2
    0x4852d4439775b93dULL,  // random 95 (N 14, L 1000, r 89.206205807638554, S 8) --engine exact
    0x0723de5a4fdd74caULL,  // random 96 (N 42, L 40, r 0.98493008491931633, S 14) --broadphase brute -t 1
    0x0723de5a4fdd74caULL,  // random 96 (N 42, L 40, r 0.98493008491931633, S 14) --broadphase grid -t 1
    0xb28361eeddaa8373ULL,  // random 96 (N 42, L 40, r 0.98493008491931633, S 14) --substeps 2 -t 2
    0x8f5922dfcbfa6bbbULL,  // random 96 (N 42, L 40, r 0.98493008491931633, S 14) --engine exact
    0x7e7ff5c09b3ffdd1ULL,  // random 97 (N 22, L 40, r 1.3608764794580201, S 9) --broadphase brute -t 1
    0x7e7ff5c09b3ffdd1ULL,  // random 97 (N 22, L 40, r 1.3608764794580201, S 9) --broadphase grid -t 2
    0x0cffa1f244f9c81aULL,  // random 97 (N 22, L 40, r 1.3608764794580201, S 9) --substeps 3 -t 2
    0x539236091d11bc16ULL,  // random 97 (N 22, L 40, r 1.3608764794580201, S 9) --engine exact
    0x059eb48cf8c989ffULL,  // random 98 (N 48, L 1000, r 36.418281019735971, S 19) --broadphase brute -t 1
    0x059eb48cf8c989ffULL,  // random 98 (N 48, L 1000, r 36.418281019735971, S 19) --broadphase grid -t 1
    0xdbd99a5c9a5a3df7ULL,  // random 98 (N 48, L 1000, r 36.418281019735971, S 19) --substeps 4 -t 2
    0xb24f0a20bbde3a35ULL,  // random 98 (N 48, L 1000, r 36.418281019735971, S 19) --engine exact
    0x1a56845c2b4e0817ULL,  // random 99 (N 45, L 40, r 0.47576643097407229, S 20) --broadphase brute -t 1
    0x1a56845c2b4e0817ULL,  // random 99 (N 45, L 40, r 0.47576643097407229, S 20) --broadphase grid -t 2
    0xb82fb363a4377451ULL,  // random 99 (N 45, L 40, r 0.47576643097407229, S 20) --substeps 2 -t 2
    0x56df65ecff26713dULL,  // random 99 (N 45, L 40, r 0.47576643097407229, S 20) --engine exact
    0x4fd93a12523e2d5cULL,  // random 100 (N 37, L 250, r 1.6396426722821356, S 12) --broadphase brute -t 1
    0x4fd93a12523e2d5cULL,  // random 100 (N 37, L 250, r 1.6396426722821356, S 12) --broadphase grid -t 1
    0x47a5c609f7b7f6b7ULL,  // random 100 (N 37, L 250, r 1.6396426722821356, S 12) --substeps 3 -t 2
    0xe833b54073cb53f6ULL,  // random 100 (N 37, L 250, r 1.6396426722821356, S 12) --engine exact
    0x7c6be19ca65ec4b6ULL,  // random 101 (N 56, L 1000, r 44.603102903819277, S 5) --broadphase brute -t 1
    0x7c6be19ca65ec4b6ULL,  // random 101 (N 56, L 1000, r 44.603102903819277, S 5) --broadphase grid -t 2
    0xeb37f0482234e4e6ULL,  // random 101 (N 56, L 1000, r 44.603102903819277, S 5) --substeps 4 -t 2
    0xd3e0314e75028eb4ULL,  // random 101 (N 56, L 1000, r 44.603102903819277, S 5) --engine exact
    0x0f3a14adf35b2b43ULL,  // random 102 (N 24, L 1000, r 32.573500793527998, S 9) --broadphase brute -t 1
    0x0f3a14adf35b2b43ULL,  // random 102 (N 24, L 1000, r 32.573500793527998, S 9) --broadphase grid -t 1
    0x963c8a47eef78b5dULL,  // random 102 (N 24, L 1000, r 32.573500793527998, S 9) --substeps 2 -t 2
    0xe124f27a0cc9b3b9ULL,  // random 102 (N 24, L 1000, r 32.573500793527998, S 9) --engine exact
    0x510c3302893c7e03ULL,  // random 103 (N 48, L 1000, r 11.516471649044517, S 8) --broadphase brute -t 1
    0x510c3302893c7e03ULL,  // random 103 (N 48, L 1000, r 11.516471649044517, S 8) --broadphase grid -t 2
    0x0da374114e08e098ULL,  // random 103 (N 48, L 1000, r 11.516471649044517, S 8) --substeps 3 -t 2
    0xede9a580b2272cdbULL,  // random 103 (N 48, L 1000, r 11.516471649044517, S 8) --engine exact
    0x00a0d8bf796e1915ULL,  // random 104 (N 12, L 250, r 2.8791179122611292, S 16) --broadphase brute -t 1
    0x00a0d8bf796e1915ULL,  // random 104 (N 12, L 250, r 2.8791179122611292, S 16) --broadphase grid -t 1
    0x02c6a2ab566c1f81ULL,  // random 104 (N 12, L 250, r 2.8791179122611292, S 16) --substeps 4 -t 2
    0xe2d4e301dcc32a10ULL,  // random 104 (N 12, L 250, r 2.8791179122611292, S 16) --engine exact
    0x8691f80fe3db8e94ULL,  // random 105 (N 19, L 1000, r 76.574167749597592, S 22) --broadphase brute -t 1
    0x8691f80fe3db8e94ULL,  // random 105 (N 19, L 1000, r 76.574167749597592, S 22) --broadphase grid -t 2
    0x1fbb4e4f612b2ac8ULL,  // random 105 (N 19, L 1000, r 76.574167749597592, S 22) --substeps 2 -t 2
    0x18f8756e48c8eac2ULL,  // random 105 (N 19, L 1000, r 76.574167749597592, S 22) --engine exact
    0x1ad4e52a54a55b59ULL,  // random 106 (N 59, L 100, r 4.3454332187205988, S 1) --broadphase brute -t 1
    0x1ad4e52a54a55b59ULL,  // random 106 (N 59, L 100, r 4.3454332187205988, S 1) --broadphase grid -t 1
    0x0ec8c2b3f5d960e7ULL,  // random 106 (N 59, L 100, r 4.3454332187205988, S 1) --substeps 3 -t 2
    0xd9ad220c94586e07ULL,  // random 106 (N 59, L 100, r 4.3454332187205988, S 1) --engine exact
    0xb06e889403217406ULL,  // random 107 (N 51, L 1000, r 35.33092219948194, S 7) --broadphase brute -t 1
    0xb06e889403217406ULL,  // random 107 (N 51, L 1000, r 35.33092219948194, S 7) --broadphase grid -t 2
    0x1962e1bc2ebc48baULL,  // random 107 (N 51, L 1000, r 35.33092219948194, S 7) --substeps 4 -t 2
    0x4a2e8a91a1aa73e8ULL,  // random 107 (N 51, L 1000, r 35.33092219948194, S 7) --engine exact
    0x51296a60a07dbfbaULL,  // random 108 (N 47, L 100, r 4.8686679589532087, S 18) --broadphase brute -t 1
    0x51296a60a07dbfbaULL,  // random 108 (N 47, L 100, r 4.8686679589532087, S 18) --broadphase grid -t 1
    0x84d96bd0fe407f62ULL,  // random 108 (N 47, L 100, r 4.8686679589532087, S 18) --substeps 2 -t 2
    0xe258b1c457630220ULL,  // random 108 (N 47, L 100, r 4.8686679589532087, S 18) --engine exact
    0x6cec012888859740ULL,  // random 109 (N 39, L 40, r 0.5110551266837825, S 1) --broadphase brute -t 1
    0x6cec012888859740ULL,  // random 109 (N 39, L 40, r 0.5110551266837825, S 1) --broadphase grid -t 2
    0x52ca10990c055fb1ULL,  // random 109 (N 39, L 40, r 0.5110551266837825, S 1) --substeps 3 -t 2
    0x91a24498a00bb8e0ULL,  // random 109 (N 39, L 40, r 0.5110551266837825, S 1) --engine exact
    0x9edafa6f2f040372ULL,  // random 110 (N 7, L 1000, r 60.314403509210749, S 6) --broadphase brute -t 1
    0x9edafa6f2f040372ULL,  // random 110 (N 7, L 1000, r 60.314403509210749, S 6) --broadphase grid -t 1
    0x20ad363f77e1869fULL,  // random 110 (N 7, L 1000, r 60.314403509210749, S 6) --substeps 4 -t 2
    0x20ad363f77e1869fULL,  // random 110 (N 7, L 1000, r 60.314403509210749, S 6) --engine exact
    0x6e80cf36e357f0f6ULL,  // random 111 (N 25, L 250, r 7.9788456080286538, S 25) --broadphase brute -t 1
    0x6e80cf36e357f0f6ULL,  // random 111 (N 25, L 250, r 7.9788456080286538, S 25) --broadphase grid -t 2
    0x2281f0a4eab52633ULL,  // random 111 (N 25, L 250, r 7.9788456080286538, S 25) --substeps 2 -t 2
    0xb8fc509f8f589008ULL,  // random 111 (N 25, L 250, r 7.9788456080286538, S 25) --engine exact
    0xda01aca785fa3d8dULL,  // random 112 (N 8, L 100, r 8.9206205807638543, S 18) --broadphase brute -t 1
    0xda01aca785fa3d8dULL,  // random 112 (N 8, L 100, r 8.9206205807638543, S 18) --broadphase grid -t 1
    0x2e4371d5ea6cb276ULL,  // random 112 (N 8, L 100, r 8.9206205807638543, S 18) --substeps 3 -t 2
    0x588f6d6f4e634a49ULL,  // random 112 (N 8, L 100, r 8.9206205807638543, S 18) --engine exact
    0xf34b28193d832749ULL,  // random 113 (N 29, L 40, r 1.1853075467562926, S 21) --broadphase brute -t 1
    0xf34b28193d832749ULL,  // random 113 (N 29, L 40, r 1.1853075467562926, S 21) --broadphase grid -t 2
    0x68ba2840ad13788dULL,  // random 113 (N 29, L 40, r 1.1853075467562926, S 21) --substeps 4 -t 2
    0x880ea28675d8bdd5ULL,  // random 113 (N 29, L 40, r 1.1853075467562926, S 21) --engine exact
    0x8f36acedd0cfbf70ULL,  // random 114 (N 16, L 100, r 1.9947114020071635, S 16) --broadphase brute -t 1
    0x8f36acedd0cfbf70ULL,  // random 114 (N 16, L 100, r 1.9947114020071635, S 16) --broadphase grid -t 1
    0x00ef5f36cd4d0679ULL,  // random 114 (N 16, L 100, r 1.9947114020071635, S 16) --substeps 2 -t 2
    0x8c3a73f8f2833764ULL,  // random 114 (N 16, L 100, r 1.9947114020071635, S 16) --engine exact
    0x87c45f76c5b75441ULL,  // random 115 (N 21, L 100, r 0.87056342755136329, S 22) --broadphase brute -t 1
    0x87c45f76c5b75441ULL,  // random 115 (N 21, L 100, r 0.87056342755136329, S 22) --broadphase grid -t 2
    0x42c6e7fbad8453d2ULL,  // random 115 (N 21, L 100, r 0.87056342755136329, S 22) --substeps 3 -t 2
    0xd0bf46ff1770b9e8ULL,  // random 115 (N 21, L 100, r 0.87056342755136329, S 22) --engine exact
    0xa935730fe08cbc9aULL,  // random 116 (N 50, L 100, r 3.5682482323055424, S 4) --broadphase brute -t 1
    0xa935730fe08cbc9aULL,  // random 116 (N 50, L 100, r 3.5682482323055424, S 4) --broadphase grid -t 1
    0xc2473682258b9124ULL,  // random 116 (N 50, L 100, r 3.5682482323055424, S 4) --substeps 4 -t 2
    0x51eb365b943504f4ULL,  // random 116 (N 50, L 100, r 3.5682482323055424, S 4) --engine exact
    0x5d7b52ea278ab200ULL,  // random 117 (N 29, L 250, r 11.713348673551284, S 22) --broadphase brute -t 1
    0x5d7b52ea278ab200ULL,  // random 117 (N 29, L 250, r 11.713348673551284, S 22) --broadphase grid -t 2
    0x8a230c752393b108ULL,  // random 117 (N 29, L 250, r 11.713348673551284, S 22) --substeps 2 -t 2
    0xec7eff5903880ef2ULL,  // random 117 (N 29, L 250, r 11.713348673551284, S 22) --engine exact
    0xc269034d7dcf7473ULL,  // random 118 (N 34, L 1000, r 43.271365765350744, S 18) --broadphase brute -t 1
    0xc269034d7dcf7473ULL,  // random 118 (N 34, L 1000, r 43.271365765350744, S 18) --broadphase grid -t 1
    0x880c0154f5511510ULL,  // random 118 (N 34, L 1000, r 43.271365765350744, S 18) --substeps 3 -t 2
    0x03bbeb62bfb31668ULL,  // random 118 (N 34, L 1000, r 43.271365765350744, S 18) --engine exact
    0x4451c41b014afeeaULL,  // random 119 (N 29, L 250, r 7.4081721672268293, S 7) --broadphase brute -t 1
    0x4451c41b014afeeaULL,  // random 119 (N 29, L 250, r 7.4081721672268293, S 7) --broadphase grid -t 2
    0xe144b4631fe24cd7ULL,  // random 119 (N 29, L 250, r 7.4081721672268293, S 7) --substeps 4 -t 2
    0x712699aa1afdc933ULL,  // random 119 (N 29, L 250, r 7.4081721672268293, S 7) --engine exact
    0x64408d69bffcef81ULL,  // random 120 (N 4, L 1000, r 39.894228040143268, S 20) --broadphase brute -t 1
    0x64408d69bffcef81ULL,  // random 120 (N 4, L 1000, r 39.894228040143268, S 20) --broadphase grid -t 1
    0x64408d69bffcef81ULL,  // random 120 (N 4, L 1000, r 39.894228040143268, S 20) --substeps 2 -t 2
    0xa4306f7922336c52ULL,  // random 120 (N 4, L 1000, r 39.894228040143268, S 20) --engine exact
    0x19fc5dcced040533ULL,  // random 121 (N 2, L 100, r 23.601743597065742, S 23) --broadphase brute -t 1
    0x19fc5dcced040533ULL,  // random 121 (N 2, L 100, r 23.601743597065742, S 23) --broadphase grid -t 2
    0xe45ac74bdce17331ULL,  // random 121 (N 2, L 100, r 23.601743597065742, S 23) --substeps 3 -t 2
    0xe7e074d08d5d51feULL,  // random 121 (N 2, L 100, r 23.601743597065742, S 23) --engine exact
    0x110331b90ae78e36ULL,  // random 122 (N 55, L 1000, r 34.021911986450498, S 13) --broadphase brute -t 1
    0x110331b90ae78e36ULL,  // random 122 (N 55, L 1000, r 34.021911986450498, S 13) --broadphase grid -t 1
    0x43a36ffcab7327deULL,  // random 122 (N 55, L 1000, r 34.021911986450498, S 13) --substeps 4 -t 2
    0xa3e9af88d19872e1ULL,  // random 122 (N 55, L 1000, r 34.021911986450498, S 13) --engine exact
    0xaee3ac13d0b2fdacULL,  // random 123 (N 24, L 250, r 8.1433751983819995, S 5) --broadphase brute -t 1
    0xaee3ac13d0b2fdacULL,  // random 123 (N 24, L 250, r 8.1433751983819995, S 5) --broadphase grid -t 2
    0x2c445ac0fffe773eULL,  // random 123 (N 24, L 250, r 8.1433751983819995, S 5) --substeps 2 -t 2
    0x1e6dbd59eaa99711ULL,  // random 123 (N 24, L 250, r 8.1433751983819995, S 5) --engine exact
    0x93497163d81eede3ULL,  // random 124 (N 44, L 40, r 1.5215061585243648, S 24) --broadphase brute -t 1
    0x93497163d81eede3ULL,  // random 124 (N 44, L 40, r 1.5215061585243648, S 24) --broadphase grid -t 1
    0xd70f4b2c5bdf7a72ULL,  // random 124 (N 44, L 40, r 1.5215061585243648, S 24) --substeps 3 -t 2
    0xec92b122fdebc36cULL,  // random 124 (N 44, L 40, r 1.5215061585243648, S 24) --engine exact
    0xb44404445bb7bd55ULL,  // random 125 (N 43, L 100, r 0.60838127406447584, S 25) --broadphase brute -t 1
    0xb44404445bb7bd55ULL,  // random 125 (N 43, L 100, r 0.60838127406447584, S 25) --broadphase grid -t 2
    0x32dd3e3a5c7e6b50ULL,  // random 125 (N 43, L 100, r 0.60838127406447584, S 25) --substeps 4 -t 2
    0xa0a21a947a5f0a12ULL,  // random 125 (N 43, L 100, r 0.60838127406447584, S 25) --engine exact
    0x84896df438cc3816ULL,  // random 126 (N 7, L 40, r 0.60314403509210746, S 24) --broadphase brute -t 1
    0x84896df438cc3816ULL,  // random 126 (N 7, L 40, r 0.60314403509210746, S 24) --broadphase grid -t 1
    0x8f422584ae2d7763ULL,  // random 126 (N 7, L 40, r 0.60314403509210746, S 24) --substeps 2 -t 2
    0x4c1bd35046b0f122ULL,  // random 126 (N 7, L 40, r 0.60314403509210746, S 24) --engine exact
    0x7e7bf6d4c206a516ULL,  // random 127 (N 2, L 250, r 59.004358992664351, S 16) --broadphase brute -t 1
    0x7e7bf6d4c206a516ULL,  // random 127 (N 2, L 250, r 59.004358992664351, S 16) --broadphase grid -t 2
    0xab7062376d71d868ULL,  // random 127 (N 2, L 250, r 59.004358992664351, S 16) --substeps 3 -t 2
    0x15294716fb2f9e0aULL,  // random 127 (N 2, L 250, r 59.004358992664351, S 16) --engine exact
    0xbd596c8078b20781ULL,  // random 128 (N 36, L 250, r 10.513052175084001, S 4) --broadphase brute -t 1
    0xbd596c8078b20781ULL,  // random 128 (N 36, L 250, r 10.513052175084001, S 4) --broadphase grid -t 1
    0xe799759916ea2e5cULL,  // random 128 (N 36, L 250, r 10.513052175084001, S 4) --substeps 4 -t 2
    0x0fd86643514d1921ULL,  // random 128 (N 36, L 250, r 10.513052175084001, S 4) --engine exact
    0xd7960f004facb856ULL,  // random 129 (N 36, L 40, r 1.0638460810704873, S 15) --broadphase brute -t 1
    0xd7960f004facb856ULL,  // random 129 (N 36, L 40, r 1.0638460810704873, S 15) --broadphase grid -t 2
    0x74803b95f5b23804ULL,  // random 129 (N 36, L 40, r 1.0638460810704873, S 15) --substeps 2 -t 2
    0xd9620e206a2659b3ULL,  // random 129 (N 36, L 40, r 1.0638460810704873, S 15) --engine exact
    0x6f818c5f4c67e417ULL,  // random 130 (N 2, L 250, r 7.0523697943469541, S 2) --broadphase brute -t 1
    0x6f818c5f4c67e417ULL,  // random 130 (N 2, L 250, r 7.0523697943469541, S 2) --broadphase grid -t 1
    0x6f818c5f4c67e417ULL,  // random 130 (N 2, L 250, r 7.0523697943469541, S 2) --substeps 3 -t 2
    0x6f818c5f4c67e417ULL,  // random 130 (N 2, L 250, r 7.0523697943469541, S 2) --engine exact
    0xaae1a28be8a467bdULL,  // random 131 (N 46, L 1000, r 49.213037368674783, S 1) --broadphase brute -t 1
    0xaae1a28be8a467bdULL,  // random 131 (N 46, L 1000, r 49.213037368674783, S 1) --broadphase grid -t 2
    0x7fe39bdf2139c996ULL,  // random 131 (N 46, L 1000, r 49.213037368674783, S 1) --substeps 4 -t 2
    0x4d9c5bff5fc85115ULL,  // random 131 (N 46, L 1000, r 49.213037368674783, S 1) --engine exact
    0x34b952ac9a05b402ULL,  // random 132 (N 29, L 40, r 1.1853075467562926, S 7) --broadphase brute -t 1
    0x34b952ac9a05b402ULL,  // random 132 (N 29, L 40, r 1.1853075467562926, S 7) --broadphase grid -t 1
    0x63d8e72e27179c85ULL,  // random 132 (N 29, L 40, r 1.1853075467562926, S 7) --substeps 2 -t 2
    0xbde5aef8062fd452ULL,  // random 132 (N 29, L 40, r 1.1853075467562926, S 7) --engine exact
    0x76657cfb9f678557ULL,  // random 133 (N 52, L 100, r 2.2129336122121508, S 18) --broadphase brute -t 1
    0x76657cfb9f678557ULL,  // random 133 (N 52, L 100, r 2.2129336122121508, S 18) --broadphase grid -t 2
    0x43a29ee8b135d277ULL,  // random 133 (N 52, L 100, r 2.2129336122121508, S 18) --substeps 3 -t 2
    0x4f4e173de41a7cc2ULL,  // random 133 (N 52, L 100, r 2.2129336122121508, S 18) --engine exact
    0xd41b5ed2a4157998ULL,  // random 134 (N 20, L 100, r 0.89206205807638561, S 20) --broadphase brute -t 1
    0xd41b5ed2a4157998ULL,  // random 134 (N 20, L 100, r 0.89206205807638561, S 20) --broadphase grid -t 1
    0x46599eca71f88e28ULL,  // random 134 (N 20, L 100, r 0.89206205807638561, S 20) --substeps 4 -t 2
    0x529a68c54b61b248ULL,  // random 134 (N 20, L 100, r 0.89206205807638561, S 20) --engine exact
    0xe9d86a339b19561bULL,  // random 135 (N 5, L 1000, r 112.83791670955127, S 18) --broadphase brute -t 1
    0xe9d86a339b19561bULL,  // random 135 (N 5, L 1000, r 112.83791670955127, S 18) --broadphase grid -t 2
    0xed86d1c03ad22564ULL,  // random 135 (N 5, L 1000, r 112.83791670955127, S 18) --substeps 2 -t 2
    0xbb82ce2b9b772f1aULL,  // random 135 (N 5, L 1000, r 112.83791670955127, S 18) --engine exact
    0x3ef47bcc7baefbe6ULL,  // random 136 (N 9, L 250, r 27.814921575518937, S 7) --broadphase brute -t 1
    0x3ef47bcc7baefbe6ULL,  // random 136 (N 9, L 250, r 27.814921575518937, S 7) --broadphase grid -t 1
    0xd0d2448d2976fd70ULL,  // random 136 (N 9, L 250, r 27.814921575518937, S 7) --substeps 3 -t 2
    0xff9f4fad09f8a8f2ULL,  // random 136 (N 9, L 250, r 27.814921575518937, S 7) --engine exact
    0x58f534eecab695b3ULL,  // random 137 (N 54, L 40, r 1.3734193849713408, S 24) --broadphase brute -t 1
    0x58f534eecab695b3ULL,  // random 137 (N 54, L 40, r 1.3734193849713408, S 24) --broadphase grid -t 2
    0xfad825ac443070baULL,  // random 137 (N 54, L 40, r 1.3734193849713408, S 24) --substeps 4 -t 2
    0x0dfabd07d3bfe40aULL,  // random 137 (N 54, L 40, r 1.3734193849713408, S 24) --engine exact
    0xd5317f1ff9baf6e7ULL,  // random 138 (N 22, L 100, r 3.4021911986450508, S 17) --broadphase brute -t 1
    0xd5317f1ff9baf6e7ULL,  // random 138 (N 22, L 100, r 3.4021911986450508, S 17) --broadphase grid -t 1
    0x1dac16b93dbdeacaULL,  // random 138 (N 22, L 100, r 3.4021911986450508, S 17) --substeps 2 -t 2
    0x85e8fe90bbaf0479ULL,  // random 138 (N 22, L 100, r 3.4021911986450508, S 17) --engine exact
    0x25b35d718cf77cbeULL,  // random 139 (N 24, L 40, r 0.65147001587055997, S 2) --broadphase brute -t 1
    0x25b35d718cf77cbeULL,  // random 139 (N 24, L 40, r 0.65147001587055997, S 2) --broadphase grid -t 2
    0xc23ac43782b10e80ULL,  // random 139 (N 24, L 40, r 0.65147001587055997, S 2) --substeps 3 -t 2
    0x802a84e84180150eULL,  // random 139 (N 24, L 40, r 0.65147001587055997, S 2) --engine exact
    0x36d1e9a666478a22ULL,  // random 140 (N 23, L 40, r 0.66548172672398365, S 25) --broadphase brute -t 1
    0x36d1e9a666478a22ULL,  // random 140 (N 23, L 40, r 0.66548172672398365, S 25) --broadphase grid -t 1
    0x48bc947f97411fb7ULL,  // random 140 (N 23, L 40, r 0.66548172672398365, S 25) --substeps 4 -t 2
    0x20d3aee5618330eeULL,  // random 140 (N 23, L 40, r 0.66548172672398365, S 25) --engine exact
    0x995914861b0e37aaULL,  // random 141 (N 12, L 250, r 2.8791179122611292, S 14) --broadphase brute -t 1
    0x995914861b0e37aaULL,  // random 141 (N 12, L 250, r 2.8791179122611292, S 14) --broadphase grid -t 2
    0xef33aed928bd307fULL,  // random 141 (N 12, L 250, r 2.8791179122611292, S 14) --substeps 2 -t 2
    0xf98897d43b9170afULL,  // random 141 (N 12, L 250, r 2.8791179122611292, S 14) --engine exact
    0xcb3d0e3e062fbf3dULL,  // random 142 (N 9, L 1000, r 53.19230405352436, S 23) --broadphase brute -t 1
    0xcb3d0e3e062fbf3dULL,  // random 142 (N 9, L 1000, r 53.19230405352436, S 23) --broadphase grid -t 1
    0x10b4604ebe22f6cbULL,  // random 142 (N 9, L 1000, r 53.19230405352436, S 23) --substeps 3 -t 2
    0x1f85fed8153f7a1fULL,  // random 142 (N 9, L 1000, r 53.19230405352436, S 23) --engine exact
    0x32e5ea4e314b93f5ULL,  // random 143 (N 47, L 1000, r 48.686679589532083, S 2) --broadphase brute -t 1
    0x32e5ea4e314b93f5ULL,  // random 143 (N 47, L 1000, r 48.686679589532083, S 2) --broadphase grid -t 2
    0x6f19fe5008a80b1bULL,  // random 143 (N 47, L 1000, r 48.686679589532083, S 2) --substeps 4 -t 2
    0x7b1eb6a1f269516eULL,  // random 143 (N 47, L 1000, r 48.686679589532083, S 2) --engine exact
    0x1c8bff964ae5d24fULL,  // random 144 (N 55, L 1000, r 21.517346446193446, S 10) --broadphase brute -t 1
    0x1c8bff964ae5d24fULL,  // random 144 (N 55, L 1000, r 21.517346446193446, S 10) --broadphase grid -t 1
    0x7f51ab61139762f5ULL,  // random 144 (N 55, L 1000, r 21.517346446193446, S 10) --substeps 2 -t 2
    0xe881b50d8493e027ULL,  // random 144 (N 55, L 1000, r 21.517346446193446, S 10) --engine exact
    0x0f2d9a1064f629a9ULL,  // random 145 (N 18, L 1000, r 18.806319451591875, S 8) --broadphase brute -t 1
    0x0f2d9a1064f629a9ULL,  // random 145 (N 18, L 1000, r 18.806319451591875, S 8) --broadphase grid -t 2
    0xa52d99a774569d0cULL,  // random 145 (N 18, L 1000, r 18.806319451591875, S 8) --substeps 3 -t 2
    0xea355eb38e8159a3ULL,  // random 145 (N 18, L 1000, r 18.806319451591875, S 8) --engine exact
    0x8fac3455bec9ef40ULL,  // random 146 (N 26, L 1000, r 49.482699866005277, S 16) --broadphase brute -t 1
    0x8fac3455bec9ef40ULL,  // random 146 (N 26, L 1000, r 49.482699866005277, S 16) --broadphase grid -t 1
    0xa644232c9a4a3606ULL,  // random 146 (N 26, L 1000, r 49.482699866005277, S 16) --substeps 4 -t 2
    0xe283c56785fb5015ULL,  // random 146 (N 26, L 1000, r 49.482699866005277, S 16) --engine exact
    0x41edd630a5ffb26cULL,  // random 147 (N 52, L 1000, r 34.989552626670999, S 3) --broadphase brute -t 1
    0x41edd630a5ffb26cULL,  // random 147 (N 52, L 1000, r 34.989552626670999, S 3) --broadphase grid -t 2
    0xfc8ec80f7917fb7eULL,  // random 147 (N 52, L 1000, r 34.989552626670999, S 3) --substeps 2 -t 2
    0x490e059e628a618cULL,  // random 147 (N 52, L 1000, r 34.989552626670999, S 3) --engine exact
    0x4b707b79fd064d6cULL,  // random 148 (N 4, L 1000, r 19.947114020071634, S 4) --broadphase brute -t 1
    0x4b707b79fd064d6cULL,  // random 148 (N 4, L 1000, r 19.947114020071634, S 4) --broadphase grid -t 1
    0x4b707b79fd064d6cULL,  // random 148 (N 4, L 1000, r 19.947114020071634, S 4) --substeps 3 -t 2
    0x4b707b79fd064d6cULL,  // random 148 (N 4, L 1000, r 19.947114020071634, S 4) --engine exact
    0x9fe69af52223c75dULL,  // random 149 (N 58, L 1000, r 20.953475102574131, S 6) --broadphase brute -t 1
    0x9fe69af52223c75dULL,  // random 149 (N 58, L 1000, r 20.953475102574131, S 6) --broadphase grid -t 2
    0xd804189a63a20144ULL,  // random 149 (N 58, L 1000, r 20.953475102574131, S 6) --substeps 4 -t 2
    0x92f47df52c245893ULL,  // random 149 (N 58, L 1000, r 20.953475102574131, S 6) --engine exact
    0x4c29623207296f76ULL,  // random 150 (N 53, L 100, r 2.1919574647566731, S 3) --broadphase brute -t 1
    0x4c29623207296f76ULL,  // random 150 (N 53, L 100, r 2.1919574647566731, S 3) --broadphase grid -t 1
    0xcfb4a4f3a48491efULL,  // random 150 (N 53, L 100, r 2.1919574647566731, S 3) --substeps 2 -t 2
    0x69e9f9c798db43f4ULL,  // random 150 (N 53, L 100, r 2.1919574647566731, S 3) --engine exact
    0xb07516b32694c658ULL,  // random 151 (N 19, L 250, r 9.152363603029011, S 21) --broadphase brute -t 1
    0xb07516b32694c658ULL,  // random 151 (N 19, L 250, r 9.152363603029011, S 21) --broadphase grid -t 2
    0x4904900705cde589ULL,  // random 151 (N 19, L 250, r 9.152363603029011, S 21) --substeps 3 -t 2
    0xddf35c0bfb182e79ULL,  // random 151 (N 19, L 250, r 9.152363603029011, S 21) --engine exact
    0x9ef0acab99da3974ULL,  // random 152 (N 28, L 1000, r 30.157201754605374, S 5) --broadphase brute -t 1
    0x9ef0acab99da3974ULL,  // random 152 (N 28, L 1000, r 30.157201754605374, S 5) --broadphase grid -t 1
    0xb103363461e6d7ccULL,  // random 152 (N 28, L 1000, r 30.157201754605374, S 5) --substeps 4 -t 2
    0x40bf6a0424ddac8eULL,  // random 152 (N 28, L 1000, r 30.157201754605374, S 5) --engine exact
    0x593b6ce62402ebc2ULL,  // random 153 (N 12, L 1000, r 11.516471649044517, S 13) --broadphase brute -t 1
    0x593b6ce62402ebc2ULL,  // random 153 (N 12, L 1000, r 11.516471649044517, S 13) --broadphase grid -t 2
    0xda36e7502d1f6d5dULL,  // random 153 (N 12, L 1000, r 11.516471649044517, S 13) --substeps 2 -t 2
    0xdc842643b998cbb5ULL,  // random 153 (N 12, L 1000, r 11.516471649044517, S 13) --engine exact
    0xbcb72d61e0ea4464ULL,  // random 154 (N 26, L 100, r 3.1295607270217074, S 2) --broadphase brute -t 1
    0xbcb72d61e0ea4464ULL,  // random 154 (N 26, L 100, r 3.1295607270217074, S 2) --broadphase grid -t 1
    0xa86e3b3e16c8d189ULL,  // random 154 (N 26, L 100, r 3.1295607270217074, S 2) --substeps 3 -t 2
    0x9f24a66ac3cea5c0ULL,  // random 154 (N 26, L 100, r 3.1295607270217074, S 2) --engine exact
    0xff67fdb54b61d18fULL,  // random 155 (N 41, L 1000, r 24.921726682684344, S 3) --broadphase brute -t 1
    0xff67fdb54b61d18fULL,  // random 155 (N 41, L 1000, r 24.921726682684344, S 3) --broadphase grid -t 2
    0x7597582d7bc6a5f3ULL,  // random 155 (N 41, L 1000, r 24.921726682684344, S 3) --substeps 4 -t 2
    0x43558ac004ad55d0ULL,  // random 155 (N 41, L 1000, r 24.921726682684344, S 3) --engine exact
    0xb0b1bc19ef18e03bULL,  // random 156 (N 16, L 1000, r 83.444764726556826, S 3) --broadphase brute -t 1
    0xb0b1bc19ef18e03bULL,  // random 156 (N 16, L 1000, r 83.444764726556826, S 3) --broadphase grid -t 1
    0x7d75f19bdb54269bULL,  // random 156 (N 16, L 1000, r 83.444764726556826, S 3) --substeps 2 -t 2
    0xd7c806c8e6010761ULL,  // random 156 (N 16, L 1000, r 83.444764726556826, S 3) --engine exact
    0x4eeb7ff454432a37ULL,  // random 157 (N 48, L 40, r 1.9270742950937028, S 23) --broadphase brute -t 1
    0x4eeb7ff454432a37ULL,  // random 157 (N 48, L 40, r 1.9270742950937028, S 23) --broadphase grid -t 2
    0x83b7ebb06a3084fbULL,  // random 157 (N 48, L 40, r 1.9270742950937028, S 23) --substeps 3 -t 2
    0x97d954ea90cf90f5ULL,  // random 157 (N 48, L 40, r 1.9270742950937028, S 23) --engine exact
    0xddf16fbc5b7c922aULL,  // random 158 (N 54, L 100, r 3.4335484624283521, S 13) --broadphase brute -t 1
    0xddf16fbc5b7c922aULL,  // random 158 (N 54, L 100, r 3.4335484624283521, S 13) --broadphase grid -t 1
    0x3ff7130d8171d32cULL,  // random 158 (N 54, L 100, r 3.4335484624283521, S 13) --substeps 4 -t 2
    0xcf42dae3570ea38cULL,  // random 158 (N 54, L 100, r 3.4335484624283521, S 13) --engine exact
    0x9dd3f18722ea75c5ULL,  // random 159 (N 43, L 100, r 0.60838127406447584, S 18) --broadphase brute -t 1
    0x9dd3f18722ea75c5ULL,  // random 159 (N 43, L 100, r 0.60838127406447584, S 18) --broadphase grid -t 2
    0x263a07dc17dcee3bULL,  // random 159 (N 43, L 100, r 0.60838127406447584, S 18) --substeps 2 -t 2
    0xc426a20257730e26ULL,  // random 159 (N 43, L 100, r 0.60838127406447584, S 18) --engine exact
    0x99b9be7b2281de4fULL,  // random 160 (N 26, L 100, r 3.1295607270217074, S 3) --broadphase brute -t 1
    0x99b9be7b2281de4fULL,  // random 160 (N 26, L 100, r 3.1295607270217074, S 3) --broadphase grid -t 1
    0xe7d304a747aa0ca0ULL,  // random 160 (N 26, L 100, r 3.1295607270217074, S 3) --substeps 3 -t 2
    0x292489e0180a8d2dULL,  // random 160 (N 26, L 100, r 3.1295607270217074, S 3) --engine exact
    0x175660cb22241c8cULL,  // random 161 (N 44, L 250, r 3.0071405843188797, S 3) --broadphase brute -t 1
    0x175660cb22241c8cULL,  // random 161 (N 44, L 250, r 3.0071405843188797, S 3) --broadphase grid -t 2
    0x2cfbc4b70fbbc1fcULL,  // random 161 (N 44, L 250, r 3.0071405843188797, S 3) --substeps 4 -t 2
    0x5876176f14d556acULL,  // random 161 (N 44, L 250, r 3.0071405843188797, S 3) --engine exact
    0x4b3132ec129f453fULL,  // random 162 (N 22, L 100, r 3.4021911986450508, S 12) --broadphase brute -t 1
    0x4b3132ec129f453fULL,  // random 162 (N 22, L 100, r 3.4021911986450508, S 12) --broadphase grid -t 1
    0x9603c21c15e3734eULL,  // random 162 (N 22, L 100, r 3.4021911986450508, S 12) --substeps 2 -t 2
    0x2b5f6f46c40610c9ULL,  // random 162 (N 22, L 100, r 3.4021911986450508, S 12) --engine exact
    0x27e510539368c8c0ULL,  // random 163 (N 5, L 250, r 8.9206205807638561, S 11) --broadphase brute -t 1
    0x27e510539368c8c0ULL,  // random 163 (N 5, L 250, r 8.9206205807638561, S 11) --broadphase grid -t 2
    0x8189b0949a94966dULL,  // random 163 (N 5, L 250, r 8.9206205807638561, S 11) --substeps 3 -t 2
    0x9b33d30042162f16ULL,  // random 163 (N 5, L 250, r 8.9206205807638561, S 11) --engine exact
    0xa01484b1f2d0236bULL,  // random 164 (N 23, L 100, r 3.327408633619918, S 24) --broadphase brute -t 1
    0xa01484b1f2d0236bULL,  // random 164 (N 23, L 100, r 3.327408633619918, S 24) --broadphase grid -t 1
    0xa7f48f723227d336ULL,  // random 164 (N 23, L 100, r 3.327408633619918, S 24) --substeps 4 -t 2
    0x5f2cd078f80c829bULL,  // random 164 (N 23, L 100, r 3.327408633619918, S 24) --engine exact
    0xd19999913bc58cabULL,  // random 165 (N 58, L 100, r 1.0476737551287065, S 13) --broadphase brute -t 1
    0xd19999913bc58cabULL,  // random 165 (N 58, L 100, r 1.0476737551287065, S 13) --broadphase grid -t 2
    0x61fe96c010c5773cULL,  // random 165 (N 58, L 100, r 1.0476737551287065, S 13) --substeps 2 -t 2
    0x2768d91d023dd283ULL,  // random 165 (N 58, L 100, r 1.0476737551287065, S 13) --engine exact
    0x4b576f68f2a26e98ULL,  // random 166 (N 34, L 100, r 4.3271365765350751, S 9) --broadphase brute -t 1
    0x4b576f68f2a26e98ULL,  // random 166 (N 34, L 100, r 4.3271365765350751, S 9) --broadphase grid -t 1
    0x4e3a90b02d325490ULL,  // random 166 (N 34, L 100, r 4.3271365765350751, S 9) --substeps 3 -t 2
    0xd3cd7833681beed8ULL,  // random 166 (N 34, L 100, r 4.3271365765350751, S 9) --engine exact
    0x71a1f74dfa4eacedULL,  // random 167 (N 52, L 250, r 1.3830835076325942, S 4) --broadphase brute -t 1
    0x71a1f74dfa4eacedULL,  // random 167 (N 52, L 250, r 1.3830835076325942, S 4) --broadphase grid -t 2
    0xf87c906b06aa4ba6ULL,  // random 167 (N 52, L 250, r 1.3830835076325942, S 4) --substeps 4 -t 2
    0x4e2ba8063fac0c00ULL,  // random 167 (N 52, L 250, r 1.3830835076325942, S 4) --engine exact
    0x1485d3e726281c16ULL,  // random 168 (N 28, L 100, r 0.75393004386513429, S 25) --broadphase brute -t 1
    0x1485d3e726281c16ULL,  // random 168 (N 28, L 100, r 0.75393004386513429, S 25) --broadphase grid -t 1
    0xd81ea9576462e9e0ULL,  // random 168 (N 28, L 100, r 0.75393004386513429, S 25) --substeps 2 -t 2
    0xadba83e21d760677ULL,  // random 168 (N 28, L 100, r 0.75393004386513429, S 25) --engine exact
    0x1d416ca842871c22ULL,  // random 169 (N 35, L 250, r 1.6858388283618386, S 16) --broadphase brute -t 1
    0x1d416ca842871c22ULL,  // random 169 (N 35, L 250, r 1.6858388283618386, S 16) --broadphase grid -t 2
    0xe86f757ebdb82da3ULL,  // random 169 (N 35, L 250, r 1.6858388283618386, S 16) --substeps 3 -t 2
    0x9c538bcccf995570ULL,  // random 169 (N 35, L 250, r 1.6858388283618386, S 16) --engine exact
    0x959f40bf97fe752dULL,  // random 170 (N 9, L 250, r 3.3245190033452725, S 5) --broadphase brute -t 1
    0x959f40bf97fe752dULL,  // random 170 (N 9, L 250, r 3.3245190033452725, S 5) --broadphase grid -t 1
    0x5b6f45979b808519ULL,  // random 170 (N 9, L 250, r 3.3245190033452725, S 5) --substeps 4 -t 2
    0xb85ae06d298d5b38ULL,  // random 170 (N 9, L 250, r 3.3245190033452725, S 5) --engine exact
    0xff899efd46d94a7cULL,  // random 171 (N 27, L 100, r 3.0710591064118713, S 7) --broadphase brute -t 1
    0xff899efd46d94a7cULL,  // random 171 (N 27, L 100, r 3.0710591064118713, S 7) --broadphase grid -t 2
    0xa8a2688fc619e666ULL,  // random 171 (N 27, L 100, r 3.0710591064118713, S 7) --substeps 2 -t 2
    0xeac7f9fd8126f62fULL,  // random 171 (N 27, L 100, r 3.0710591064118713, S 7) --engine exact
    0xbcc9f76a9610e14fULL,  // random 172 (N 31, L 100, r 4.5316797867100913, S 20) --broadphase brute -t 1
    0xbcc9f76a9610e14fULL,  // random 172 (N 31, L 100, r 4.5316797867100913, S 20) --broadphase grid -t 1
    0x886eed8d9937b381ULL,  // random 172 (N 31, L 100, r 4.5316797867100913, S 20) --substeps 3 -t 2
    0xf0de1d7e1bbcd754ULL,  // random 172 (N 31, L 100, r 4.5316797867100913, S 20) --engine exact
    0x07bea4e2a0582f6fULL,  // random 173 (N 50, L 100, r 2.2567583341910251, S 25) --broadphase brute -t 1
    0x07bea4e2a0582f6fULL,  // random 173 (N 50, L 100, r 2.2567583341910251, S 25) --broadphase grid -t 2
    0x962f16afe8e0059bULL,  // random 173 (N 50, L 100, r 2.2567583341910251, S 25) --substeps 4 -t 2
    0x9a28799b41f79dbeULL,  // random 173 (N 50, L 100, r 2.2567583341910251, S 25) --engine exact
    0x9737981720dcf477ULL,  // random 174 (N 46, L 250, r 2.9410415107641361, S 17) --broadphase brute -t 1
    0x9737981720dcf477ULL,  // random 174 (N 46, L 250, r 2.9410415107641361, S 17) --broadphase grid -t 1
    0x2555afc864c4f98dULL,  // random 174 (N 46, L 250, r 2.9410415107641361, S 17) --substeps 2 -t 2
    0x2308163b19c5eb88ULL,  // random 174 (N 46, L 250, r 2.9410415107641361, S 17) --engine exact
    0xc341da5624608a76ULL,  // random 175 (N 43, L 40, r 2.0360331716064759, S 25) --broadphase brute -t 1
    0xc341da5624608a76ULL,  // random 175 (N 43, L 40, r 2.0360331716064759, S 25) --broadphase grid -t 2
    0x5732a7c0d8f23b5dULL,  // random 175 (N 43, L 40, r 2.0360331716064759, S 25) --substeps 3 -t 2
    0xb0f42b2e9c2e3529ULL,  // random 175 (N 43, L 40, r 2.0360331716064759, S 25) --engine exact
    0xe2d455fc5d026920ULL,  // random 176 (N 1, L 250, r 9.9735570100358171, S 15) --broadphase brute -t 1
    0xe2d455fc5d026920ULL,  // random 176 (N 1, L 250, r 9.9735570100358171, S 15) --broadphase grid -t 1
    0xe2d455fc5d026920ULL,  // random 176 (N 1, L 250, r 9.9735570100358171, S 15) --substeps 4 -t 2
    0xe2d455fc5d026920ULL,  // random 176 (N 1, L 250, r 9.9735570100358171, S 15) --engine exact
    0x43b9a96b282834f1ULL,  // random 177 (N 5, L 40, r 5.9708213214418464, S 24) --broadphase brute -t 1
    0x43b9a96b282834f1ULL,  // random 177 (N 5, L 40, r 5.9708213214418464, S 24) --broadphase grid -t 2
    0x4ee605e859718b62ULL,  // random 177 (N 5, L 40, r 5.9708213214418464, S 24) --substeps 2 -t 2
    0x49e706330a37b6c9ULL,  // random 177 (N 5, L 40, r 5.9708213214418464, S 24) --engine exact
    0xc0d09e017b81937cULL,  // random 178 (N 1, L 250, r 9.9735570100358171, S 2) --broadphase brute -t 1
    0xc0d09e017b81937cULL,  // random 178 (N 1, L 250, r 9.9735570100358171, S 2) --broadphase grid -t 1
    0xc0d09e017b81937cULL,  // random 178 (N 1, L 250, r 9.9735570100358171, S 2) --substeps 3 -t 2
    0xc0d09e017b81937cULL,  // random 178 (N 1, L 250, r 9.9735570100358171, S 2) --engine exact
    0xe88242bae3ada5a1ULL,  // random 179 (N 7, L 1000, r 126.156626101008, S 7) --broadphase brute -t 1
    0xe88242bae3ada5a1ULL,  // random 179 (N 7, L 1000, r 126.156626101008, S 7) --broadphase grid -t 2
    0x7627bbcfd64c1d07ULL,  // random 179 (N 7, L 1000, r 126.156626101008, S 7) --substeps 4 -t 2
    0x3fdf8edf0bcb1157ULL,  // random 179 (N 7, L 1000, r 126.156626101008, S 7) --engine exact
    0x614bbc301e8d03c4ULL,  // random 180 (N 28, L 250, r 11.920680675222403, S 11) --broadphase brute -t 1
    0x614bbc301e8d03c4ULL,  // random 180 (N 28, L 250, r 11.920680675222403, S 11) --broadphase grid -t 1
    0x96855b3da719608aULL,  // random 180 (N 28, L 250, r 11.920680675222403, S 11) --substeps 2 -t 2
    0xd66995df0864a5afULL,  // random 180 (N 28, L 250, r 11.920680675222403, S 11) --engine exact
    0x134f4303a07f5552ULL,  // random 181 (N 4, L 1000, r 166.88952945311365, S 9) --broadphase brute -t 1
    0x134f4303a07f5552ULL,  // random 181 (N 4, L 1000, r 166.88952945311365, S 9) --broadphase grid -t 2
    0xc83bdf74c734e137ULL,  // random 181 (N 4, L 1000, r 166.88952945311365, S 9) --substeps 3 -t 2
    0xee15cfd94f8bb387ULL,  // random 181 (N 4, L 1000, r 166.88952945311365, S 9) --engine exact
    0x1785f461d0bf752aULL,  // random 182 (N 27, L 250, r 1.9194119415074196, S 3) --broadphase brute -t 1
    0x1785f461d0bf752aULL,  // random 182 (N 27, L 250, r 1.9194119415074196, S 3) --broadphase grid -t 1
    0x02d1682a583e5b44ULL,  // random 182 (N 27, L 250, r 1.9194119415074196, S 3) --substeps 4 -t 2
    0x55b2bf8dd2c7a266ULL,  // random 182 (N 27, L 250, r 1.9194119415074196, S 3) --engine exact
    0xbe8fc3e33892a9f2ULL,  // random 183 (N 37, L 250, r 1.6396426722821356, S 3) --broadphase brute -t 1
    0xbe8fc3e33892a9f2ULL,  // random 183 (N 37, L 250, r 1.6396426722821356, S 3) --broadphase grid -t 2
    0xbd96cba7cf831529ULL,  // random 183 (N 37, L 250, r 1.6396426722821356, S 3) --substeps 2 -t 2
    0xd0f4cf0a5500a623ULL,  // random 183 (N 37, L 250, r 1.6396426722821356, S 3) --engine exact
    0x276b93e205bc448dULL,  // random 184 (N 44, L 1000, r 38.037653963109115, S 21) --broadphase brute -t 1
    0x276b93e205bc448dULL,  // random 184 (N 44, L 1000, r 38.037653963109115, S 21) --broadphase grid -t 1
    0xa902514f4c5478b0ULL,  // random 184 (N 44, L 1000, r 38.037653963109115, S 21) --substeps 3 -t 2
    0x00bf0a1cc22ad9aeULL,  // random 184 (N 44, L 1000, r 38.037653963109115, S 21) --engine exact
    0xc009968d036aa2d0ULL,  // random 185 (N 29, L 250, r 7.4081721672268293, S 14) --broadphase brute -t 1
    0xc009968d036aa2d0ULL,  // random 185 (N 29, L 250, r 7.4081721672268293, S 14) --broadphase grid -t 2
    0xd326c37c43b01a7bULL,  // random 185 (N 29, L 250, r 7.4081721672268293, S 14) --substeps 4 -t 2
    0x2aed21929ba104e3ULL,  // random 185 (N 29, L 250, r 7.4081721672268293, S 14) --engine exact
    0xfbf524148f1222f0ULL,  // random 186 (N 47, L 100, r 4.8686679589532087, S 17) --broadphase brute -t 1
    0xfbf524148f1222f0ULL,  // random 186 (N 47, L 100, r 4.8686679589532087, S 17) --broadphase grid -t 1
    0x7ff180a8a8ef27d4ULL,  // random 186 (N 47, L 100, r 4.8686679589532087, S 17) --substeps 2 -t 2
    0x9c66cb8abe3f8eb9ULL,  // random 186 (N 47, L 100, r 4.8686679589532087, S 17) --engine exact
    0xf5231db50b4bb52eULL,  // random 187 (N 39, L 250, r 1.5970472708868202, S 20) --broadphase brute -t 1
    0xf5231db50b4bb52eULL,  // random 187 (N 39, L 250, r 1.5970472708868202, S 20) --broadphase grid -t 2
    0xa196c678fb0999bbULL,  // random 187 (N 39, L 250, r 1.5970472708868202, S 20) --substeps 3 -t 2
    0xffccac1d94df9c89ULL,  // random 187 (N 39, L 250, r 1.5970472708868202, S 20) --engine exact
    0xa8da16c75d06b485ULL,  // random 188 (N 43, L 1000, r 50.900829290161894, S 21) --broadphase brute -t 1
    0xa8da16c75d06b485ULL,  // random 188 (N 43, L 1000, r 50.900829290161894, S 21) --broadphase grid -t 1
    0x094c0ac658f88284ULL,  // random 188 (N 43, L 1000, r 50.900829290161894, S 21) --substeps 4 -t 2
    0x1482da07a326ecacULL,  // random 188 (N 43, L 1000, r 50.900829290161894, S 21) --engine exact
    0xfabe714f8653d817ULL,  // random 189 (N 6, L 40, r 0.65147001587055997, S 9) --broadphase brute -t 1
    0xfabe714f8653d817ULL,  // random 189 (N 6, L 40, r 0.65147001587055997, S 9) --broadphase grid -t 2
    0x974a36ef527d3282ULL,  // random 189 (N 6, L 40, r 0.65147001587055997, S 9) --substeps 2 -t 2
    0xb735f02ba4dd9cfdULL,  // random 189 (N 6, L 40, r 0.65147001587055997, S 9) --engine exact
    0xa0bba5cda3c4af1cULL,  // random 190 (N 11, L 1000, r 76.07530792621823, S 22) --broadphase brute -t 1
    0xa0bba5cda3c4af1cULL,  // random 190 (N 11, L 1000, r 76.07530792621823, S 22) --broadphase grid -t 1
    0x5b60df8cfa4cdc25ULL,  // random 190 (N 11, L 1000, r 76.07530792621823, S 22) --substeps 3 -t 2
    0x84f68877a9d8b679ULL,  // random 190 (N 11, L 1000, r 76.07530792621823, S 22) --engine exact
    0x7654db858ce488e8ULL,  // random 191 (N 38, L 100, r 4.0930614342335536, S 24) --broadphase brute -t 1
    0x7654db858ce488e8ULL,  // random 191 (N 38, L 100, r 4.0930614342335536, S 24) --broadphase grid -t 2
    0x807353edd76fadc0ULL,  // random 191 (N 38, L 100, r 4.0930614342335536, S 24) --substeps 4 -t 2
    0x351150408c41b267ULL,  // random 191 (N 38, L 100, r 4.0930614342335536, S 24) --engine exact
    0xd08788b08d2f1f4dULL,  // random 192 (N 23, L 100, r 5.2610949941738294, S 20) --broadphase brute -t 1
    0xd08788b08d2f1f4dULL,  // random 192 (N 23, L 100, r 5.2610949941738294, S 20) --broadphase grid -t 1
    0x8fe6d2b054ad550bULL,  // random 192 (N 23, L 100, r 5.2610949941738294, S 20) --substeps 2 -t 2
    0xd1e59ea77d5349edULL,  // random 192 (N 23, L 100, r 5.2610949941738294, S 20) --engine exact
    0xfccdfcdc5ee14bd0ULL,  // random 193 (N 48, L 1000, r 5.7582358245222585, S 14) --broadphase brute -t 1
    0xfccdfcdc5ee14bd0ULL,  // random 193 (N 48, L 1000, r 5.7582358245222585, S 14) --broadphase grid -t 2
    0x6c4087652bad8f11ULL,  // random 193 (N 48, L 1000, r 5.7582358245222585, S 14) --substeps 3 -t 2
    0xf1ebf125d9007fdcULL,  // random 193 (N 48, L 1000, r 5.7582358245222585, S 14) --engine exact
    0x8ae287cbcbc62f91ULL,  // random 194 (N 41, L 40, r 0.4984345336536869, S 4) --broadphase brute -t 1
    0x8ae287cbcbc62f91ULL,  // random 194 (N 41, L 40, r 0.4984345336536869, S 4) --broadphase grid -t 1
    0x36ae101498d07b3fULL,  // random 194 (N 41, L 40, r 0.4984345336536869, S 4) --substeps 4 -t 2
    0xc2104535b56778e5ULL,  // random 194 (N 41, L 40, r 0.4984345336536869, S 4) --engine exact
    0x8755e563f3621774ULL,  // random 195 (N 48, L 250, r 9.1045702549339929, S 5) --broadphase brute -t 1
    0x8755e563f3621774ULL,  // random 195 (N 48, L 250, r 9.1045702549339929, S 5) --broadphase grid -t 2
    0xf7ba3f9da16a6704ULL,  // random 195 (N 48, L 250, r 9.1045702549339929, S 5) --substeps 2 -t 2
    0x354efdcbb4ec8643ULL,  // random 195 (N 48, L 250, r 9.1045702549339929, S 5) --engine exact
    0xb67eb022fe33537dULL,  // random 196 (N 54, L 100, r 1.0857833597842665, S 24) --broadphase brute -t 1
    0xb67eb022fe33537dULL,  // random 196 (N 54, L 100, r 1.0857833597842665, S 24) --broadphase grid -t 1
    0x0651a88bb82f3dcdULL,  // random 196 (N 54, L 100, r 1.0857833597842665, S 24) --substeps 3 -t 2
    0xcf7f265afcd50cd0ULL,  // random 196 (N 54, L 100, r 1.0857833597842665, S 24) --engine exact
    0xd5417ce63b883cb8ULL,  // random 197 (N 34, L 250, r 14.310659088154022, S 13) --broadphase brute -t 1
    0xd5417ce63b883cb8ULL,  // random 197 (N 34, L 250, r 14.310659088154022, S 13) --broadphase grid -t 2
    0x60a2de15325ce958ULL,  // random 197 (N 34, L 250, r 14.310659088154022, S 13) --substeps 4 -t 2
    0xaaaace59fcb6835fULL,  // random 197 (N 34, L 250, r 14.310659088154022, S 13) --engine exact
    0x6f0a4a1576cfc4acULL,  // random 198 (N 55, L 100, r 3.4021911986450499, S 14) --broadphase brute -t 1
    0x6f0a4a1576cfc4acULL,  // random 198 (N 55, L 100, r 3.4021911986450499, S 14) --broadphase grid -t 1
    0xd6d225cfe2d9b61aULL,  // random 198 (N 55, L 100, r 3.4021911986450499, S 14) --substeps 2 -t 2
    0x984754e21038e94eULL,  // random 198 (N 55, L 100, r 3.4021911986450499, S 14) --engine exact
    0x374911d4838da3c8ULL,  // random 199 (N 4, L 1000, r 39.894228040143268, S 2) --broadphase brute -t 1
    0x374911d4838da3c8ULL,  // random 199 (N 4, L 1000, r 39.894228040143268, S 2) --broadphase grid -t 2
    0x374911d4838da3c8ULL,  // random 199 (N 4, L 1000, r 39.894228040143268, S 2) --substeps 3 -t 2
    0x374911d4838da3c8ULL,  // random 199 (N 4, L 1000, r 39.894228040143268, S 2) --engine exact
    0x6a910bab08ab17d7ULL,  // random 200 (N 60, L 250, r 5.1503226936425284, S 7) --broadphase brute -t 1
    0x6a910bab08ab17d7ULL,  // random 200 (N 60, L 250, r 5.1503226936425284, S 7) --broadphase grid -t 1
    0xb4353b0540dcb4c4ULL,  // random 200 (N 60, L 250, r 5.1503226936425284, S 7) --substeps 4 -t 2
    0x34e00180cac24a1dULL,  // random 200 (N 60, L 250, r 5.1503226936425284, S 7) --engine exact
    0x63eb89dd27da8834ULL,  // random 201 (N 49, L 100, r 2.2796701737224723, S 18) --broadphase brute -t 1
    0x63eb89dd27da8834ULL,  // random 201 (N 49, L 100, r 2.2796701737224723, S 18) --broadphase grid -t 2
    0x6327d0f90a8fa89fULL,  // random 201 (N 49, L 100, r 2.2796701737224723, S 18) --substeps 2 -t 2
    0xbdd951abf4c7fe4eULL,  // random 201 (N 49, L 100, r 2.2796701737224723, S 18) --engine exact
    0xff57aba92e754e48ULL,  // random 202 (N 27, L 40, r 0.61421182128237428, S 18) --broadphase brute -t 1
    0xff57aba92e754e48ULL,  // random 202 (N 27, L 40, r 0.61421182128237428, S 18) --broadphase grid -t 1
    0x8b7c0c7c1c10078fULL,  // random 202 (N 27, L 40, r 0.61421182128237428, S 18) --substeps 3 -t 2
    0x63f4e31ce8b6fbc5ULL,  // random 202 (N 27, L 40, r 0.61421182128237428, S 18) --engine exact
    0x78d1e53e8b3a7683ULL,  // random 203 (N 13, L 250, r 2.7661670152651885, S 12) --broadphase brute -t 1
    0x78d1e53e8b3a7683ULL,  // random 203 (N 13, L 250, r 2.7661670152651885, S 12) --broadphase grid -t 2
    0x252e7fdbd4f2d199ULL,  // random 203 (N 13, L 250, r 2.7661670152651885, S 12) --substeps 4 -t 2
    0xeda9716994101093ULL,  // random 203 (N 13, L 250, r 2.7661670152651885, S 12) --engine exact
    0x17d6364a1f964f21ULL,  // random 204 (N 39, L 40, r 0.25552756334189125, S 8) --broadphase brute -t 1
    0x17d6364a1f964f21ULL,  // random 204 (N 39, L 40, r 0.25552756334189125, S 8) --broadphase grid -t 1
    0xf6208d3d4705e079ULL,  // random 204 (N 39, L 40, r 0.25552756334189125, S 8) --substeps 2 -t 2
    0xaac7a52a877d23d5ULL,  // random 204 (N 39, L 40, r 0.25552756334189125, S 8) --engine exact
    0x45691b8c22f60c36ULL,  // random 205 (N 4, L 40, r 6.6755811781245455, S 10) --broadphase brute -t 1
    0x45691b8c22f60c36ULL,  // random 205 (N 4, L 40, r 6.6755811781245455, S 10) --broadphase grid -t 2
    0x74c69718065377edULL,  // random 205 (N 4, L 40, r 6.6755811781245455, S 10) --substeps 3 -t 2
    0x5dc34c21706a8bbfULL,  // random 205 (N 4, L 40, r 6.6755811781245455, S 10) --engine exact
    0xdbb454f71d27b1f1ULL,  // random 206 (N 43, L 40, r 0.97341003850316132, S 6) --broadphase brute -t 1
    0xdbb454f71d27b1f1ULL,  // random 206 (N 43, L 40, r 0.97341003850316132, S 6) --broadphase grid -t 1
    0xa9b5e9e016ea81c5ULL,  // random 206 (N 43, L 40, r 0.97341003850316132, S 6) --substeps 4 -t 2
    0x959b7e713fa6ee57ULL,  // random 206 (N 43, L 40, r 0.97341003850316132, S 6) --engine exact
    0x414907943aa0b68aULL,  // random 207 (N 7, L 40, r 3.814617816071169, S 8) --broadphase brute -t 1
    0x414907943aa0b68aULL,  // random 207 (N 7, L 40, r 3.814617816071169, S 8) --broadphase grid -t 2
    0xea390e9ad32f34f2ULL,  // random 207 (N 7, L 40, r 3.814617816071169, S 8) --substeps 2 -t 2
    0x4cb4a7a4196f6cfeULL,  // random 207 (N 7, L 40, r 3.814617816071169, S 8) --engine exact
    0x07dfe4d159e9279dULL,  // random 208 (N 11, L 100, r 2.4057124674551034, S 24) --broadphase brute -t 1
    0x07dfe4d159e9279dULL,  // random 208 (N 11, L 100, r 2.4057124674551034, S 24) --broadphase grid -t 1
    0x6f7e268936ab5029ULL,  // random 208 (N 11, L 100, r 2.4057124674551034, S 24) --substeps 3 -t 2
    0x58e94add5045e411ULL,  // random 208 (N 11, L 100, r 2.4057124674551034, S 24) --engine exact
    0xf3ab6c9bdb81b13aULL,  // random 209 (N 7, L 40, r 3.814617816071169, S 6) --broadphase brute -t 1
    0xf3ab6c9bdb81b13aULL,  // random 209 (N 7, L 40, r 3.814617816071169, S 6) --broadphase grid -t 2
    0xeacdc141afa3f8ccULL,  // random 209 (N 7, L 40, r 3.814617816071169, S 6) --substeps 4 -t 2
    0xd59b32c585976848ULL,  // random 209 (N 7, L 40, r 3.814617816071169, S 6) --engine exact
    0x12bafa6be499550fULL,  // random 210 (N 44, L 100, r 0.60142811686377584, S 5) --broadphase brute -t 1
    0x12bafa6be499550fULL,  // random 210 (N 44, L 100, r 0.60142811686377584, S 5) --broadphase grid -t 1
    0xcc1f68db20c6634cULL,  // random 210 (N 44, L 100, r 0.60142811686377584, S 5) --substeps 2 -t 2
    0x634443e9e195ec0aULL,  // random 210 (N 44, L 100, r 0.60142811686377584, S 5) --engine exact
    0x1dc37ad766eaeed6ULL,  // random 211 (N 20, L 100, r 5.6418958354775635, S 5) --broadphase brute -t 1
    0x1dc37ad766eaeed6ULL,  // random 211 (N 20, L 100, r 5.6418958354775635, S 5) --broadphase grid -t 2
    0x61bf90a11b561331ULL,  // random 211 (N 20, L 100, r 5.6418958354775635, S 5) --substeps 3 -t 2
    0xd2692fcc2a2cb807ULL,  // random 211 (N 20, L 100, r 5.6418958354775635, S 5) --engine exact
    0xb5c1e1cb97579a8cULL,  // random 212 (N 8, L 100, r 11.800871798532871, S 8) --broadphase brute -t 1
    0xb5c1e1cb97579a8cULL,  // random 212 (N 8, L 100, r 11.800871798532871, S 8) --broadphase grid -t 1
    0x013b0f47d9fdc104ULL,  // random 212 (N 8, L 100, r 11.800871798532871, S 8) --substeps 4 -t 2
    0x3ea47c639df8d01cULL,  // random 212 (N 8, L 100, r 11.800871798532871, S 8) --engine exact
    0xe679a0f2e2457b9fULL,  // random 213 (N 4, L 250, r 41.722382363278413, S 8) --broadphase brute -t 1
    0xe679a0f2e2457b9fULL,  // random 213 (N 4, L 250, r 41.722382363278413, S 8) --broadphase grid -t 2
    0x84a068e880bedf5dULL,  // random 213 (N 4, L 250, r 41.722382363278413, S 8) --substeps 2 -t 2
    0x4f7d44a3bded7736ULL,  // random 213 (N 4, L 250, r 41.722382363278413, S 8) --engine exact
    0xe61e3aead8f38063ULL,  // random 214 (N 49, L 1000, r 11.398350868612363, S 4) --broadphase brute -t 1
    0xe61e3aead8f38063ULL,  // random 214 (N 49, L 1000, r 11.398350868612363, S 4) --broadphase grid -t 1
    0x6c8d9f9a822c45b5ULL,  // random 214 (N 49, L 1000, r 11.398350868612363, S 4) --substeps 3 -t 2
    0x1a3e45a7d6d98358ULL,  // random 214 (N 49, L 1000, r 11.398350868612363, S 4) --engine exact
    0x83a1548c9ffd7074ULL,  // random 215 (N 17, L 100, r 8.0953312675860829, S 17) --broadphase brute -t 1
    0x83a1548c9ffd7074ULL,  // random 215 (N 17, L 100, r 8.0953312675860829, S 17) --broadphase grid -t 2
    0x9f9abdbe788a8bd1ULL,  // random 215 (N 17, L 100, r 8.0953312675860829, S 17) --substeps 4 -t 2
    0xf3218f4005e2a4caULL,  // random 215 (N 17, L 100, r 8.0953312675860829, S 17) --engine exact
    0xcaf440101bf1fe17ULL,  // random 216 (N 11, L 40, r 1.9245699739640829, S 2) --broadphase brute -t 1
    0xcaf440101bf1fe17ULL,  // random 216 (N 11, L 40, r 1.9245699739640829, S 2) --broadphase grid -t 1
    0x8d98c5628dadb30fULL,  // random 216 (N 11, L 40, r 1.9245699739640829, S 2) --substeps 2 -t 2
    0x12ecdbf1b3996235ULL,  // random 216 (N 11, L 40, r 1.9245699739640829, S 2) --engine exact
    0x199aa2e21147e956ULL,  // random 217 (N 50, L 250, r 1.4104739588693909, S 4) --broadphase brute -t 1
    0x199aa2e21147e956ULL,  // random 217 (N 50, L 250, r 1.4104739588693909, S 4) --broadphase grid -t 2
    0xdcc9b4ec50a3461aULL,  // random 217 (N 50, L 250, r 1.4104739588693909, S 4) --substeps 3 -t 2
    0x000b7602c596b2b1ULL,  // random 217 (N 50, L 250, r 1.4104739588693909, S 4) --engine exact
    0x05b658c1fd896342ULL,  // random 218 (N 27, L 40, r 1.2284236425647486, S 21) --broadphase brute -t 1
    0x05b658c1fd896342ULL,  // random 218 (N 27, L 40, r 1.2284236425647486, S 21) --broadphase grid -t 1
    0x4f2de85f28ea6ef0ULL,  // random 218 (N 27, L 40, r 1.2284236425647486, S 21) --substeps 4 -t 2
    0xe392da623c4ec559ULL,  // random 218 (N 27, L 40, r 1.2284236425647486, S 21) --engine exact
    0xa296b8de3294b511ULL,  // random 219 (N 51, L 100, r 2.2345237196913765, S 20) --broadphase brute -t 1
    0xa296b8de3294b511ULL,  // random 219 (N 51, L 100, r 2.2345237196913765, S 20) --broadphase grid -t 2
    0x9e10a34299ab9133ULL,  // random 219 (N 51, L 100, r 2.2345237196913765, S 20) --substeps 2 -t 2
    0x015075aac05615f7ULL,  // random 219 (N 51, L 100, r 2.2345237196913765, S 20) --engine exact
    0xed8c1a900fccd8d6ULL,  // random 220 (N 11, L 100, r 7.6075307926218239, S 12) --broadphase brute -t 1
    0xed8c1a900fccd8d6ULL,  // random 220 (N 11, L 100, r 7.6075307926218239, S 12) --broadphase grid -t 1
    0x9099e97662d9140dULL,  // random 220 (N 11, L 100, r 7.6075307926218239, S 12) --substeps 3 -t 2
    0x3c4d507b6f47a6e4ULL,  // random 220 (N 11, L 100, r 7.6075307926218239, S 12) --engine exact
    0x5f9202f2bbff52deULL,  // random 221 (N 56, L 100, r 1.0662180931146152, S 3) --broadphase brute -t 1
    0x5f9202f2bbff52deULL,  // random 221 (N 56, L 100, r 1.0662180931146152, S 3) --broadphase grid -t 2
    0xc45d164b5573755fULL,  // random 221 (N 56, L 100, r 1.0662180931146152, S 3) --substeps 4 -t 2
    0x15ca998cafa25e24ULL,  // random 221 (N 56, L 100, r 1.0662180931146152, S 3) --engine exact
    0x3588c1c7a18cd9a9ULL,  // random 222 (N 6, L 250, r 8.1433751983819995, S 6) --broadphase brute -t 1
    0x3588c1c7a18cd9a9ULL,  // random 222 (N 6, L 250, r 8.1433751983819995, S 6) --broadphase grid -t 1
    0x92f9bd44bfdf9b2bULL,  // random 222 (N 6, L 250, r 8.1433751983819995, S 6) --substeps 2 -t 2
    0x0551f2e27bc0f866ULL,  // random 222 (N 6, L 250, r 8.1433751983819995, S 6) --engine exact
    0x1df9e9a5c23be1f4ULL,  // random 223 (N 58, L 250, r 10.956834397062977, S 8) --broadphase brute -t 1
    0x1df9e9a5c23be1f4ULL,  // random 223 (N 58, L 250, r 10.956834397062977, S 8) --broadphase grid -t 2
    0x2e89645c50dc69d3ULL,  // random 223 (N 58, L 250, r 10.956834397062977, S 8) --substeps 3 -t 2
    0x968d1c26406b5676ULL,  // random 223 (N 58, L 250, r 10.956834397062977, S 8) --engine exact
    0x7f96d18340a72c18ULL,  // random 224 (N 43, L 1000, r 50.900829290161894, S 4) --broadphase brute -t 1
    0x7f96d18340a72c18ULL,  // random 224 (N 43, L 1000, r 50.900829290161894, S 4) --broadphase grid -t 1
    0x4d506cc0b8488741ULL,  // random 224 (N 43, L 1000, r 50.900829290161894, S 4) --substeps 4 -t 2
    0x2963716eca649969ULL,  // random 224 (N 43, L 1000, r 50.900829290161894, S 4) --engine exact
    0xdec2bb4959681296ULL,  // random 225 (N 21, L 40, r 2.2023706229642319, S 25) --broadphase brute -t 1
    0xdec2bb4959681296ULL,  // random 225 (N 21, L 40, r 2.2023706229642319, S 25) --broadphase grid -t 2
    0x5deabfb7b7709d34ULL,  // random 225 (N 21, L 40, r 2.2023706229642319, S 25) --substeps 2 -t 2
    0x850e9384d985711fULL,  // random 225 (N 21, L 40, r 2.2023706229642319, S 25) --engine exact
    0xb7880678aa815638ULL,  // random 226 (N 11, L 250, r 19.018826981554557, S 18) --broadphase brute -t 1
    0xb7880678aa815638ULL,  // random 226 (N 11, L 250, r 19.018826981554557, S 18) --broadphase grid -t 1
    0xd61bd53dcb5f4e73ULL,  // random 226 (N 11, L 250, r 19.018826981554557, S 18) --substeps 3 -t 2
    0x20cf9e45aa90edd7ULL,  // random 226 (N 11, L 250, r 19.018826981554557, S 18) --engine exact
    0x660cc82e0194b34fULL,  // random 227 (N 22, L 1000, r 8.5054779966126262, S 19) --broadphase brute -t 1
    0x660cc82e0194b34fULL,  // random 227 (N 22, L 1000, r 8.5054779966126262, S 19) --broadphase grid -t 2
    0x6470e652df261fbeULL,  // random 227 (N 22, L 1000, r 8.5054779966126262, S 19) --substeps 4 -t 2
    0x6e87ff98990c46e9ULL,  // random 227 (N 22, L 1000, r 8.5054779966126262, S 19) --engine exact
    0x251cc719a5db72f4ULL,  // random 228 (N 49, L 40, r 0.45593403474449451, S 25) --broadphase brute -t 1
    0x251cc719a5db72f4ULL,  // random 228 (N 49, L 40, r 0.45593403474449451, S 25) --broadphase grid -t 1
    0x71b1815c067e9f36ULL,  // random 228 (N 49, L 40, r 0.45593403474449451, S 25) --substeps 2 -t 2
    0x6a5998de2cad25c1ULL,  // random 228 (N 49, L 40, r 0.45593403474449451, S 25) --engine exact
    0x5ec0d78c3be8e705ULL,  // random 229 (N 40, L 250, r 9.9735570100358171, S 3) --broadphase brute -t 1
    0x5ec0d78c3be8e705ULL,  // random 229 (N 40, L 250, r 9.9735570100358171, S 3) --broadphase grid -t 2
    0x5eda753f9402ac80ULL,  // random 229 (N 40, L 250, r 9.9735570100358171, S 3) --substeps 3 -t 2
    0x0bdb569ebbbb0d6aULL,  // random 229 (N 40, L 250, r 9.9735570100358171, S 3) --engine exact
    0xe975afd5bafedd6cULL,  // random 230 (N 10, L 250, r 3.1539156525252001, S 8) --broadphase brute -t 1
    0xe975afd5bafedd6cULL,  // random 230 (N 10, L 250, r 3.1539156525252001, S 8) --broadphase grid -t 1
    0x166531867e2071d5ULL,  // random 230 (N 10, L 250, r 3.1539156525252001, S 8) --substeps 4 -t 2
    0x166531867e2071d5ULL,  // random 230 (N 10, L 250, r 3.1539156525252001, S 8) --engine exact
    0x520cb34955b9d2b5ULL,  // random 231 (N 59, L 250, r 5.1937861029668992, S 1) --broadphase brute -t 1
    0x520cb34955b9d2b5ULL,  // random 231 (N 59, L 250, r 5.1937861029668992, S 1) --broadphase grid -t 2
    0x4dde97d00c0d2e1aULL,  // random 231 (N 59, L 250, r 5.1937861029668992, S 1) --substeps 2 -t 2
    0x606a3bb0dd1c77dfULL,  // random 231 (N 59, L 250, r 5.1937861029668992, S 1) --engine exact
    0xf397a1e57792768aULL,  // random 232 (N 3, L 100, r 9.2131773192356139, S 11) --broadphase brute -t 1
    0xf397a1e57792768aULL,  // random 232 (N 3, L 100, r 9.2131773192356139, S 11) --broadphase grid -t 1
    0x00b93dc20d411e67ULL,  // random 232 (N 3, L 100, r 9.2131773192356139, S 11) --substeps 3 -t 2
    0x8c680c7a2b779d86ULL,  // random 232 (N 3, L 100, r 9.2131773192356139, S 11) --engine exact
    0x2dcd82ba88f42722ULL,  // random 233 (N 22, L 100, r 5.3793366115483616, S 10) --broadphase brute -t 1
    0x2dcd82ba88f42722ULL,  // random 233 (N 22, L 100, r 5.3793366115483616, S 10) --broadphase grid -t 2
    0xf1a3630729ec5e2fULL,  // random 233 (N 22, L 100, r 5.3793366115483616, S 10) --substeps 4 -t 2
    0xee848b2ebf50555fULL,  // random 233 (N 22, L 100, r 5.3793366115483616, S 10) --engine exact
    0x9c5849f652f2c5cdULL,  // random 234 (N 34, L 1000, r 57.242636352616088, S 14) --broadphase brute -t 1
    0x9c5849f652f2c5cdULL,  // random 234 (N 34, L 1000, r 57.242636352616088, S 14) --broadphase grid -t 1
    0x7403952cef2c25c3ULL,  // random 234 (N 34, L 1000, r 57.242636352616088, S 14) --substeps 2 -t 2
    0xcb23199a6ca05f31ULL,  // random 234 (N 34, L 1000, r 57.242636352616088, S 14) --engine exact
    0x3f6d041afe01343eULL,  // random 235 (N 22, L 250, r 4.2527389983063131, S 1) --broadphase brute -t 1
    0x3f6d041afe01343eULL,  // random 235 (N 22, L 250, r 4.2527389983063131, S 1) --broadphase grid -t 2
    0xb31389322b6d7572ULL,  // random 235 (N 22, L 250, r 4.2527389983063131, S 1) --substeps 3 -t 2
    0x36849d1eb9addb0fULL,  // random 235 (N 22, L 250, r 4.2527389983063131, S 1) --engine exact
    0x27edbfafa6857f36ULL,  // random 236 (N 59, L 100, r 3.2848387530210426, S 24) --broadphase brute -t 1
    0x27edbfafa6857f36ULL,  // random 236 (N 59, L 100, r 3.2848387530210426, S 24) --broadphase grid -t 1
    0x98a939bf4102a563ULL,  // random 236 (N 59, L 100, r 3.2848387530210426, S 24) --substeps 4 -t 2
    0x3a6811a00d5eab86ULL,  // random 236 (N 59, L 100, r 3.2848387530210426, S 24) --engine exact
    0x907e7effe80999f4ULL,  // random 237 (N 31, L 250, r 14.98712217126641, S 5) --broadphase brute -t 1
    0x907e7effe80999f4ULL,  // random 237 (N 31, L 250, r 14.98712217126641, S 5) --broadphase grid -t 2
    0x89a6bc1f53e86790ULL,  // random 237 (N 31, L 250, r 14.98712217126641, S 5) --substeps 2 -t 2
    0xf04ac80e72d0873aULL,  // random 237 (N 31, L 250, r 14.98712217126641, S 5) --engine exact
    0xf5a283ea13b71de2ULL,  // random 238 (N 26, L 250, r 16.364864755687389, S 20) --broadphase brute -t 1
    0xf5a283ea13b71de2ULL,  // random 238 (N 26, L 250, r 16.364864755687389, S 20) --broadphase grid -t 1
    0x529676cceda67f86ULL,  // random 238 (N 26, L 250, r 16.364864755687389, S 20) --substeps 3 -t 2
    0x95071dbc9e59b2dbULL,  // random 238 (N 26, L 250, r 16.364864755687389, S 20) --engine exact
    0xb791d89a6e4093b9ULL,  // random 239 (N 36, L 40, r 0.26596152026762182, S 9) --broadphase brute -t 1
    0xb791d89a6e4093b9ULL,  // random 239 (N 36, L 40, r 0.26596152026762182, S 9) --broadphase grid -t 2
    0xae3b66c5aae7e1a0ULL,  // random 239 (N 36, L 40, r 0.26596152026762182, S 9) --substeps 4 -t 2
    0x8827f031827d636aULL,  // random 239 (N 36, L 40, r 0.26596152026762182, S 9) --engine exact
    0x54db449e31830190ULL,  // random 240 (N 284, L 40, r 0.094691476211689898, S 8) --broadphase brute -t 1
    0x54db449e31830190ULL,  // random 240 (N 284, L 40, r 0.094691476211689898, S 8) --broadphase grid -t 1
    0xf3c4c9f6b03f7759ULL,  // random 240 (N 284, L 40, r 0.094691476211689898, S 8) --substeps 2 -t 2
    0xff006c64f4307ceeULL,  // random 240 (N 284, L 40, r 0.094691476211689898, S 8) --engine exact
    0xaecfed37c0705d0cULL,  // random 241 (N 270, L 250, r 1.2139427006578656, S 3) --broadphase brute -t 1
    0xaecfed37c0705d0cULL,  // random 241 (N 270, L 250, r 1.2139427006578656, S 3) --broadphase grid -t 2
    0x27656251ee08da05ULL,  // random 241 (N 270, L 250, r 1.2139427006578656, S 3) --substeps 3 -t 2
    0xc99d62ec2e080e06ULL,  // random 241 (N 270, L 250, r 1.2139427006578656, S 3) --engine exact
    0x2c3471519f0c4af2ULL,  // random 242 (N 386, L 40, r 0.67955627145200292, S 1) --broadphase brute -t 1
    0x2c3471519f0c4af2ULL,  // random 242 (N 386, L 40, r 0.67955627145200292, S 1) --broadphase grid -t 1
    0x30732187a63e92c0ULL,  // random 242 (N 386, L 40, r 0.67955627145200292, S 1) --substeps 4 -t 2
    0x690d646d508e05b8ULL,  // random 242 (N 386, L 40, r 0.67955627145200292, S 1) --engine exact
    0xbc4d4127355f3c3bULL,  // random 243 (N 236, L 40, r 0.65696775060420842, S 3) --broadphase brute -t 1
    0xbc4d4127355f3c3bULL,  // random 243 (N 236, L 40, r 0.65696775060420842, S 3) --broadphase grid -t 2
    0xf88fa9ea42b97370ULL,  // random 243 (N 236, L 40, r 0.65696775060420842, S 3) --substeps 2 -t 2
    0xffbc55460bb2a135ULL,  // random 243 (N 236, L 40, r 0.65696775060420842, S 3) --engine exact
    0x1275026c1429e30dULL,  // random 244 (N 306, L 100, r 0.91224048856495643, S 4) --broadphase brute -t 1
    0x1275026c1429e30dULL,  // random 244 (N 306, L 100, r 0.91224048856495643, S 4) --broadphase grid -t 1
    0x10913fd26da4c915ULL,  // random 244 (N 306, L 100, r 0.91224048856495643, S 4) --substeps 3 -t 2
    0x5583b894f448e37fULL,  // random 244 (N 306, L 100, r 0.91224048856495643, S 4) --engine exact
    0xa265bf65d544c1ffULL,  // random 245 (N 26, L 250, r 1.9559754543885672, S 7) --broadphase brute -t 1
    0xa265bf65d544c1ffULL,  // random 245 (N 26, L 250, r 1.9559754543885672, S 7) --broadphase grid -t 2
    0x005a8341eb072e6dULL,  // random 245 (N 26, L 250, r 1.9559754543885672, S 7) --substeps 4 -t 2
    0x72c1ed85142cad8bULL,  // random 245 (N 26, L 250, r 1.9559754543885672, S 7) --engine exact
    0xe5532d3235e98efaULL,  // random 246 (N 284, L 40, r 0.59888147966518501, S 1) --broadphase brute -t 1
    0xe5532d3235e98efaULL,  // random 246 (N 284, L 40, r 0.59888147966518501, S 1) --broadphase grid -t 1
    0x7a10af08992fea74ULL,  // random 246 (N 284, L 40, r 0.59888147966518501, S 1) --substeps 2 -t 2
    0xd0463edd4c54f7faULL,  // random 246 (N 284, L 40, r 0.59888147966518501, S 1) --engine exact
    0xfa4027bafab31015ULL,  // random 247 (N 69, L 40, r 0.76843210812973783, S 1) --broadphase brute -t 1
    0xfa4027bafab31015ULL,  // random 247 (N 69, L 40, r 0.76843210812973783, S 1) --broadphase grid -t 2
    0x976a05096aa93d49ULL,  // random 247 (N 69, L 40, r 0.76843210812973783, S 1) --substeps 3 -t 2
    0x0ba63c1bcbb8e3d8ULL,  // random 247 (N 69, L 40, r 0.76843210812973783, S 1) --engine exact
    0x708c295bfd18efb1ULL,  // random 248 (N 10, L 250, r 6.3078313050504002, S 5) --broadphase brute -t 1
    0x708c295bfd18efb1ULL,  // random 248 (N 10, L 250, r 6.3078313050504002, S 5) --broadphase grid -t 1
    0xa618b88fd1ca6f48ULL,  // random 248 (N 10, L 250, r 6.3078313050504002, S 5) --substeps 4 -t 2
    0x29f303ac1217866aULL,  // random 248 (N 10, L 250, r 6.3078313050504002, S 5) --engine exact
    0xc6aeaf70cb8eae40ULL,  // random 249 (N 207, L 100, r 0.55456810560331971, S 8) --broadphase brute -t 1
    0xc6aeaf70cb8eae40ULL,  // random 249 (N 207, L 100, r 0.55456810560331971, S 8) --broadphase grid -t 2
    0x0c49bf9e7c0542d7ULL,  // random 249 (N 207, L 100, r 0.55456810560331971, S 8) --substeps 2 -t 2
    0x38459f8331947950ULL,  // random 249 (N 207, L 100, r 0.55456810560331971, S 8) --engine exact
    0xf0abaf168ccd86a5ULL,  // random 250 (N 292, L 100, r 0.4669266216322408, S 3) --broadphase brute -t 1
    0xf0abaf168ccd86a5ULL,  // random 250 (N 292, L 100, r 0.4669266216322408, S 3) --broadphase grid -t 1
    0xf843d7dbd1d9d276ULL,  // random 250 (N 292, L 100, r 0.4669266216322408, S 3) --substeps 3 -t 2
    0x99713913e388e84fULL,  // random 250 (N 292, L 100, r 0.4669266216322408, S 3) --engine exact
    0x1c102410475d89fbULL,  // random 251 (N 213, L 100, r 0.54670149280782199, S 6) --broadphase brute -t 1
    0x1c102410475d89fbULL,  // random 251 (N 213, L 100, r 0.54670149280782199, S 6) --broadphase grid -t 2
    0x599ce48dee4091bcULL,  // random 251 (N 213, L 100, r 0.54670149280782199, S 6) --substeps 4 -t 2
    0x125e28e67b5d4fa2ULL,  // random 251 (N 213, L 100, r 0.54670149280782199, S 6) --engine exact
    0xa7ec3fa4f78f2759ULL,  // random 252 (N 393, L 1000, r 8.0495903985536206, S 3) --broadphase brute -t 1
    0xa7ec3fa4f78f2759ULL,  // random 252 (N 393, L 1000, r 8.0495903985536206, S 3) --broadphase grid -t 1
    0xd5b847d79ca3474cULL,  // random 252 (N 393, L 1000, r 8.0495903985536206, S 3) --substeps 2 -t 2
    0xf5999a03e4c7c6bcULL,  // random 252 (N 393, L 1000, r 8.0495903985536206, S 3) --engine exact
    0x6cd60a7109622d74ULL,  // random 253 (N 372, L 1000, r 17.305638039916939, S 2) --broadphase brute -t 1
    0x6cd60a7109622d74ULL,  // random 253 (N 372, L 1000, r 17.305638039916939, S 2) --broadphase grid -t 2
    0x97fcf17b4997a443ULL,  // random 253 (N 372, L 1000, r 17.305638039916939, S 2) --substeps 3 -t 2
    0x2cb74c07e536e26dULL,  // random 253 (N 372, L 1000, r 17.305638039916939, S 2) --engine exact
    0x2effcf7fbb045bb5ULL,  // random 254 (N 40, L 250, r 13.193775767639851, S 5) --broadphase brute -t 1
    0x2effcf7fbb045bb5ULL,  // random 254 (N 40, L 250, r 13.193775767639851, S 5) --broadphase grid -t 1
    0x1004ce88b0a2e8c1ULL,  // random 254 (N 40, L 250, r 13.193775767639851, S 5) --substeps 4 -t 2
    0xf965f7e28cfd404fULL,  // random 254 (N 40, L 250, r 13.193775767639851, S 5) --engine exact
    0x68b85d7932b93274ULL,  // random 255 (N 324, L 40, r 0.74173124201383833, S 5) --broadphase brute -t 1
    0x68b85d7932b93274ULL,  // random 255 (N 324, L 40, r 0.74173124201383833, S 5) --broadphase grid -t 2
    0x74091df48c63e0f6ULL,  // random 255 (N 324, L 40, r 0.74173124201383833, S 5) --substeps 2 -t 2
    0x307eae1a7cae9af9ULL,  // random 255 (N 324, L 40, r 0.74173124201383833, S 5) --engine exact
    0x268897af33d417efULL,  // random 256 (N 62, L 250, r 2.5332860138363782, S 6) --broadphase brute -t 1
    0x268897af33d417efULL,  // random 256 (N 62, L 250, r 2.5332860138363782, S 6) --broadphase grid -t 1
    0x96ef8fef02d2bbf6ULL,  // random 256 (N 62, L 250, r 2.5332860138363782, S 6) --substeps 3 -t 2
    0x74ebec71c494b9bdULL,  // random 256 (N 62, L 250, r 2.5332860138363782, S 6) --engine exact
    0x9361923003d9ad67ULL,  // random 257 (N 27, L 1000, r 30.710591064118713, S 6) --broadphase brute -t 1
    0x9361923003d9ad67ULL,  // random 257 (N 27, L 1000, r 30.710591064118713, S 6) --broadphase grid -t 2
    0x9d6a0db8dceadeb2ULL,  // random 257 (N 27, L 1000, r 30.710591064118713, S 6) --substeps 4 -t 2
    0x123233ff32a71901ULL,  // random 257 (N 27, L 1000, r 30.710591064118713, S 6) --engine exact
    0x66adaa15928b4ffcULL,  // random 258 (N 148, L 100, r 0.32792853445642711, S 7) --broadphase brute -t 1
    0x66adaa15928b4ffcULL,  // random 258 (N 148, L 100, r 0.32792853445642711, S 7) --broadphase grid -t 1
    0x038dfe9cedc4e01dULL,  // random 258 (N 148, L 100, r 0.32792853445642711, S 7) --substeps 2 -t 2
    0xd5b3073b63c38369ULL,  // random 258 (N 148, L 100, r 0.32792853445642711, S 7) --engine exact
    0xe7cd508fd9b88ae0ULL,  // random 259 (N 287, L 40, r 0.09419527292100785, S 5) --broadphase brute -t 1
    0xe7cd508fd9b88ae0ULL,  // random 259 (N 287, L 40, r 0.09419527292100785, S 5) --broadphase grid -t 2
    0xdabc1e84d061c1cfULL,  // random 259 (N 287, L 40, r 0.09419527292100785, S 5) --substeps 3 -t 2
    0x15e9296ad070f6c2ULL,  // random 259 (N 287, L 40, r 0.09419527292100785, S 5) --engine exact
    0xe8bd81df822e185fULL,  // random 260 (N 138, L 40, r 0.54336355454001195, S 7) --broadphase brute -t 1
    0xe8bd81df822e185fULL,  // random 260 (N 138, L 40, r 0.54336355454001195, S 7) --broadphase grid -t 1
    0x95d5a3ee2fa73dcfULL,  // random 260 (N 138, L 40, r 0.54336355454001195, S 7) --substeps 4 -t 2
    0xb0d3c3faf75548c6ULL,  // random 260 (N 138, L 40, r 0.54336355454001195, S 7) --engine exact
    0x0c5be0df86041eb8ULL,  // random 261 (N 308, L 40, r 0.18185476899467917, S 1) --broadphase brute -t 1
    0x0c5be0df86041eb8ULL,  // random 261 (N 308, L 40, r 0.18185476899467917, S 1) --broadphase grid -t 2
    0x005988ebcfb93663ULL,  // random 261 (N 308, L 40, r 0.18185476899467917, S 1) --substeps 2 -t 2
    0x013dc06f2a16a048ULL,  // random 261 (N 308, L 40, r 0.18185476899467917, S 1) --engine exact
    0x62656fca83f55388ULL,  // random 262 (N 381, L 250, r 1.0219216083285778, S 4) --broadphase brute -t 1
    0x62656fca83f55388ULL,  // random 262 (N 381, L 250, r 1.0219216083285778, S 4) --broadphase grid -t 1
    0x3c4401b9320270bdULL,  // random 262 (N 381, L 250, r 1.0219216083285778, S 4) --substeps 3 -t 2
    0x64aaabb168c13f02ULL,  // random 262 (N 381, L 250, r 1.0219216083285778, S 4) --engine exact
    0xbac39c544a30f2c0ULL,  // random 263 (N 119, L 40, r 0.92518071629555254, S 4) --broadphase brute -t 1
    0xbac39c544a30f2c0ULL,  // random 263 (N 119, L 40, r 0.92518071629555254, S 4) --broadphase grid -t 2
    0xd5f0c9ac3fb2d318ULL,  // random 263 (N 119, L 40, r 0.92518071629555254, S 4) --substeps 4 -t 2
    0xfec769a2463d08beULL,  // random 263 (N 119, L 40, r 0.92518071629555254, S 4) --engine exact
    0xe19596f9b4d0fc05ULL,  // random 264 (N 388, L 250, r 4.2362660932793279, S 3) --broadphase brute -t 1
    0xe19596f9b4d0fc05ULL,  // random 264 (N 388, L 250, r 4.2362660932793279, S 3) --broadphase grid -t 1
    0x78ab748cc5c9ed59ULL,  // random 264 (N 388, L 250, r 4.2362660932793279, S 3) --substeps 2 -t 2
    0xf4162e4186f0e4b8ULL,  // random 264 (N 388, L 250, r 4.2362660932793279, S 3) --engine exact
    0x194d8ef259ae80cfULL,  // random 265 (N 281, L 1000, r 2.3798901189675261, S 6) --broadphase brute -t 1
    0x194d8ef259ae80cfULL,  // random 265 (N 281, L 1000, r 2.3798901189675261, S 6) --broadphase grid -t 2
    0xce45eb6974d32faeULL,  // random 265 (N 281, L 1000, r 2.3798901189675261, S 6) --substeps 3 -t 2
    0x130878142df9e541ULL,  // random 265 (N 281, L 1000, r 2.3798901189675261, S 6) --engine exact
    0xa25e51bf1b2f8525ULL,  // random 266 (N 243, L 1000, r 2.5592159220098925, S 7) --broadphase brute -t 1
    0xa25e51bf1b2f8525ULL,  // random 266 (N 243, L 1000, r 2.5592159220098925, S 7) --broadphase grid -t 1
    0xde15036c14e8baa1ULL,  // random 266 (N 243, L 1000, r 2.5592159220098925, S 7) --substeps 4 -t 2
    0x7652526b94c8a57bULL,  // random 266 (N 243, L 1000, r 2.5592159220098925, S 7) --engine exact
    0xbf34165250c6056dULL,  // random 267 (N 183, L 100, r 0.29490661955586261, S 8) --broadphase brute -t 1
    0xbf34165250c6056dULL,  // random 267 (N 183, L 100, r 0.29490661955586261, S 8) --broadphase grid -t 2
    0x189d5514809f59d8ULL,  // random 267 (N 183, L 100, r 0.29490661955586261, S 8) --substeps 2 -t 2
    0x972493b594563d31ULL,  // random 267 (N 183, L 100, r 0.29490661955586261, S 8) --engine exact
    0x221233be3f6c0243ULL,  // random 268 (N 36, L 40, r 1.0638460810704873, S 1) --broadphase brute -t 1
    0x221233be3f6c0243ULL,  // random 268 (N 36, L 40, r 1.0638460810704873, S 1) --broadphase grid -t 1
    0x2d4a277c2666f369ULL,  // random 268 (N 36, L 40, r 1.0638460810704873, S 1) --substeps 3 -t 2
    0xef898e5dc738bd52ULL,  // random 268 (N 36, L 40, r 1.0638460810704873, S 1) --engine exact
    0x308c7cf4b85c5457ULL,  // random 269 (N 63, L 40, r 0.20104801169736913, S 2) --broadphase brute -t 1
    0x308c7cf4b85c5457ULL,  // random 269 (N 63, L 40, r 0.20104801169736913, S 2) --broadphase grid -t 2
    0x059b1f21a42d21c6ULL,  // random 269 (N 63, L 40, r 0.20104801169736913, S 2) --substeps 4 -t 2
    0x07f90c4de0267a28ULL,  // random 269 (N 63, L 40, r 0.20104801169736913, S 2) --engine exact
    0x6ce73674af76bb22ULL,  // random 270 (N 188, L 250, r 0.72739640423632057, S 8) --broadphase brute -t 1
    0x6ce73674af76bb22ULL,  // random 270 (N 188, L 250, r 0.72739640423632057, S 8) --broadphase grid -t 1
    0xe205b6ca32e6e2b9ULL,  // random 270 (N 188, L 250, r 0.72739640423632057, S 8) --substeps 2 -t 2
    0x7ddfff0be78cca4cULL,  // random 270 (N 188, L 250, r 0.72739640423632057, S 8) --engine exact
    0xa8f95d624c6dee52ULL,  // random 271 (N 180, L 1000, r 18.806319451591875, S 4) --broadphase brute -t 1
    0xa8f95d624c6dee52ULL,  // random 271 (N 180, L 1000, r 18.806319451591875, S 4) --broadphase grid -t 2
    0x22dc27ed044cfbf8ULL,  // random 271 (N 180, L 1000, r 18.806319451591875, S 4) --substeps 3 -t 2
    0xe98b9600e36f41e8ULL,  // random 271 (N 180, L 1000, r 18.806319451591875, S 4) --engine exact
    0x4867a3058732dbd3ULL,  // random 272 (N 216, L 40, r 0.90843153460736215, S 5) --broadphase brute -t 1
    0x4867a3058732dbd3ULL,  // random 272 (N 216, L 40, r 0.90843153460736215, S 5) --broadphase grid -t 1
    0xea07b1df1bcddb5eULL,  // random 272 (N 216, L 40, r 0.90843153460736215, S 5) --substeps 4 -t 2
    0x7ccf30315c9f9e88ULL,  // random 272 (N 216, L 40, r 0.90843153460736215, S 5) --engine exact
    0xb02e167f5b3313efULL,  // random 273 (N 296, L 1000, r 2.31880490458706, S 1) --broadphase brute -t 1
    0xb02e167f5b3313efULL,  // random 273 (N 296, L 1000, r 2.31880490458706, S 1) --broadphase grid -t 2
    0xdaf84e4fab78d77eULL,  // random 273 (N 296, L 1000, r 2.31880490458706, S 1) --substeps 2 -t 2
    0x73be3a098d8b4b4bULL,  // random 273 (N 296, L 1000, r 2.31880490458706, S 1) --engine exact
    0xc07e3bfc281e8777ULL,  // random 274 (N 198, L 100, r 1.1340637328816834, S 7) --broadphase brute -t 1
    0xc07e3bfc281e8777ULL,  // random 274 (N 198, L 100, r 1.1340637328816834, S 7) --broadphase grid -t 1
    0x5ce9f2652cadeb91ULL,  // random 274 (N 198, L 100, r 1.1340637328816834, S 7) --substeps 3 -t 2
    0xf3c465c31e8d8ea3ULL,  // random 274 (N 198, L 100, r 1.1340637328816834, S 7) --engine exact
    0xd2dffc4ea371e4f7ULL,  // random 275 (N 135, L 40, r 1.1490850990725356, S 7) --broadphase brute -t 1
    0xd2dffc4ea371e4f7ULL,  // random 275 (N 135, L 40, r 1.1490850990725356, S 7) --broadphase grid -t 2
    0xaa5bbfebd3d83e91ULL,  // random 275 (N 135, L 40, r 1.1490850990725356, S 7) --substeps 4 -t 2
    0xd4e68b7ad0ede8e7ULL,  // random 275 (N 135, L 40, r 1.1490850990725356, S 7) --engine exact
    0xefe04c97a2aeda97ULL,  // random 276 (N 213, L 250, r 1.3667537320195551, S 7) --broadphase brute -t 1
    0xefe04c97a2aeda97ULL,  // random 276 (N 213, L 250, r 1.3667537320195551, S 7) --broadphase grid -t 1
    0x72d9a2d0663a6ffeULL,  // random 276 (N 213, L 250, r 1.3667537320195551, S 7) --substeps 2 -t 2
    0x5e70c9407dc45ed0ULL,  // random 276 (N 213, L 250, r 1.3667537320195551, S 7) --engine exact
    0x9e85810aa7f0fd6cULL,  // random 277 (N 307, L 40, r 0.36430141720594228, S 5) --broadphase brute -t 1
    0x9e85810aa7f0fd6cULL,  // random 277 (N 307, L 40, r 0.36430141720594228, S 5) --broadphase grid -t 2
    0xba7b5540037ce5eeULL,  // random 277 (N 307, L 40, r 0.36430141720594228, S 5) --substeps 3 -t 2
    0x137cbca25bbb7dbeULL,  // random 277 (N 307, L 40, r 0.36430141720594228, S 5) --engine exact
    0x959ba91137f78fd4ULL,  // random 278 (N 142, L 250, r 5.2934144424785714, S 6) --broadphase brute -t 1
    0x959ba91137f78fd4ULL,  // random 278 (N 142, L 250, r 5.2934144424785714, S 6) --broadphase grid -t 1
    0x0b9cd51d19b3654dULL,  // random 278 (N 142, L 250, r 5.2934144424785714, S 6) --substeps 4 -t 2
    0x4df3cf39c36bcbbeULL,  // random 278 (N 142, L 250, r 5.2934144424785714, S 6) --engine exact
    0xaeb97ac7c7758d6cULL,  // random 279 (N 224, L 1000, r 5.3310904655730766, S 6) --broadphase brute -t 1
    0xaeb97ac7c7758d6cULL,  // random 279 (N 224, L 1000, r 5.3310904655730766, S 6) --broadphase grid -t 2
    0x6b33187b39953456ULL,  // random 279 (N 224, L 1000, r 5.3310904655730766, S 6) --substeps 2 -t 2
    0x7e977e9585389ce2ULL,  // random 279 (N 224, L 1000, r 5.3310904655730766, S 6) --engine exact
    0x29b35cda14bf8962ULL,  // random 280 (N 247, L 40, r 0.10153635773049675, S 2) --broadphase brute -t 1
    0x29b35cda14bf8962ULL,  // random 280 (N 247, L 40, r 0.10153635773049675, S 2) --broadphase grid -t 1
    0x12cc159e2a8118cbULL,  // random 280 (N 247, L 40, r 0.10153635773049675, S 2) --substeps 3 -t 2
    0xc8b13df214386382ULL,  // random 280 (N 247, L 40, r 0.10153635773049675, S 2) --engine exact
    0xc767dfc1e83ad7fdULL,  // random 281 (N 223, L 250, r 2.6715151064072469, S 2) --broadphase brute -t 1
    0xc767dfc1e83ad7fdULL,  // random 281 (N 223, L 250, r 2.6715151064072469, S 2) --broadphase grid -t 2
    0xf1a8e8deb70db040ULL,  // random 281 (N 223, L 250, r 2.6715151064072469, S 2) --substeps 4 -t 2
    0xc58b60ac046007f2ULL,  // random 281 (N 223, L 250, r 2.6715151064072469, S 2) --engine exact
    0x8ef8f59848f35fe4ULL,  // random 282 (N 219, L 100, r 2.2554698622994156, S 8) --broadphase brute -t 1
    0x8ef8f59848f35fe4ULL,  // random 282 (N 219, L 100, r 2.2554698622994156, S 8) --broadphase grid -t 1
    0xd31d90aa5fc99a5aULL,  // random 282 (N 219, L 100, r 2.2554698622994156, S 8) --substeps 2 -t 2
    0x1fede721b1a8c806ULL,  // random 282 (N 219, L 100, r 2.2554698622994156, S 8) --engine exact
    0x16bd716bbd1b8c40ULL,  // random 283 (N 357, L 250, r 2.1114264503494233, S 3) --broadphase brute -t 1
    0x16bd716bbd1b8c40ULL,  // random 283 (N 357, L 250, r 2.1114264503494233, S 3) --broadphase grid -t 2
    0xcb04a691864411f6ULL,  // random 283 (N 357, L 250, r 2.1114264503494233, S 3) --substeps 3 -t 2
    0x07bc62c5284520f9ULL,  // random 283 (N 357, L 250, r 2.1114264503494233, S 3) --engine exact
    0xf7f6abe84bfb36a5ULL,  // random 284 (N 199, L 100, r 0.28280268445974099, S 2) --broadphase brute -t 1
    0xf7f6abe84bfb36a5ULL,  // random 284 (N 199, L 100, r 0.28280268445974099, S 2) --broadphase grid -t 1
    0x11eff661d2f2e635ULL,  // random 284 (N 199, L 100, r 0.28280268445974099, S 2) --substeps 4 -t 2
    0x5d51b00c389abd62ULL,  // random 284 (N 199, L 100, r 0.28280268445974099, S 2) --engine exact
    0x84e44307ca799cfcULL,  // random 285 (N 83, L 250, r 6.9237443533865983, S 1) --broadphase brute -t 1
    0x84e44307ca799cfcULL,  // random 285 (N 83, L 250, r 6.9237443533865983, S 1) --broadphase grid -t 2
    0xf9c8d89047aa0930ULL,  // random 285 (N 83, L 250, r 6.9237443533865983, S 1) --substeps 2 -t 2
    0xd5b5e49f0a53061bULL,  // random 285 (N 83, L 250, r 6.9237443533865983, S 1) --engine exact
    0xbb7f1da2686f2f01ULL,  // random 286 (N 146, L 100, r 0.66033396094536545, S 8) --broadphase brute -t 1
    0xbb7f1da2686f2f01ULL,  // random 286 (N 146, L 100, r 0.66033396094536545, S 8) --broadphase grid -t 1
    0x8585f2c2dd9de648ULL,  // random 286 (N 146, L 100, r 0.66033396094536545, S 8) --substeps 3 -t 2
    0x388e528ee04717f5ULL,  // random 286 (N 146, L 100, r 0.66033396094536545, S 8) --engine exact
    0x3120e246db408a08ULL,  // random 287 (N 165, L 1000, r 6.2115228814781123, S 2) --broadphase brute -t 1
    0x3120e246db408a08ULL,  // random 287 (N 165, L 1000, r 6.2115228814781123, S 2) --broadphase grid -t 2
    0x7b985d3bcd4750efULL,  // random 287 (N 165, L 1000, r 6.2115228814781123, S 2) --substeps 4 -t 2
    0xa132640d9d944592ULL,  // random 287 (N 165, L 1000, r 6.2115228814781123, S 2) --engine exact
    0x26b10656d0fc2170ULL,  // random 288 (N 65, L 40, r 1.656007879314787, S 6) --broadphase brute -t 1
    0x26b10656d0fc2170ULL,  // random 288 (N 65, L 40, r 1.656007879314787, S 6) --broadphase grid -t 1
    0x96accdcaa0ce4f55ULL,  // random 288 (N 65, L 40, r 1.656007879314787, S 6) --substeps 2 -t 2
    0x3449a3dbc434d32fULL,  // random 288 (N 65, L 40, r 1.656007879314787, S 6) --engine exact
    0xac85bda2833a2cb9ULL,  // random 289 (N 120, L 1000, r 7.2836562039471948, S 1) --broadphase brute -t 1
    0xac85bda2833a2cb9ULL,  // random 289 (N 120, L 1000, r 7.2836562039471948, S 1) --broadphase grid -t 2
    0x69aa5975b99cea73ULL,  // random 289 (N 120, L 1000, r 7.2836562039471948, S 1) --substeps 3 -t 2
    0x53b4f0f13238ae4eULL,  // random 289 (N 120, L 1000, r 7.2836562039471948, S 1) --engine exact
    0x96fc2ad252bbcf15ULL,  // random 290 (N 57, L 100, r 0.5284119589930133, S 7) --broadphase brute -t 1
    0x96fc2ad252bbcf15ULL,  // random 290 (N 57, L 100, r 0.5284119589930133, S 7) --broadphase grid -t 1
    0x7a99631c7bc10548ULL,  // random 290 (N 57, L 100, r 0.5284119589930133, S 7) --substeps 4 -t 2
    0xc3dc8a8a7d3fd3b9ULL,  // random 290 (N 57, L 100, r 0.5284119589930133, S 7) --engine exact
    0x577d80af708ea9a6ULL,  // random 291 (N 103, L 250, r 8.222056979460751, S 3) --broadphase brute -t 1
    0x577d80af708ea9a6ULL,  // random 291 (N 103, L 250, r 8.222056979460751, S 3) --broadphase grid -t 2
    0x6916a34bc0ca3007ULL,  // random 291 (N 103, L 250, r 8.222056979460751, S 3) --substeps 2 -t 2
    0xf238a4672bc76c5aULL,  // random 291 (N 103, L 250, r 8.222056979460751, S 3) --engine exact
    0x95613dacdaf5bff6ULL,  // random 292 (N 143, L 100, r 2.7912007111801866, S 8) --broadphase brute -t 1
    0x95613dacdaf5bff6ULL,  // random 292 (N 143, L 100, r 2.7912007111801866, S 8) --broadphase grid -t 1
    0x0123075b80e986e8ULL,  // random 292 (N 143, L 100, r 2.7912007111801866, S 8) --substeps 3 -t 2
    0x6d80968960e557e3ULL,  // random 292 (N 143, L 100, r 2.7912007111801866, S 8) --engine exact
    0x3dec0ac137893e01ULL,  // random 293 (N 188, L 250, r 1.4547928084726411, S 2) --broadphase brute -t 1
    0x3dec0ac137893e01ULL,  // random 293 (N 188, L 250, r 1.4547928084726411, S 2) --broadphase grid -t 2
    0x3a2a7b9bf76b471dULL,  // random 293 (N 188, L 250, r 1.4547928084726411, S 2) --substeps 4 -t 2
    0xe447814e563a0990ULL,  // random 293 (N 188, L 250, r 1.4547928084726411, S 2) --engine exact
    0xefc0ce7777fd0ec2ULL,  // random 294 (N 213, L 1000, r 17.288219174868797, S 6) --broadphase brute -t 1
    0xefc0ce7777fd0ec2ULL,  // random 294 (N 213, L 1000, r 17.288219174868797, S 6) --broadphase grid -t 1
    0x00ec1966a8da2913ULL,  // random 294 (N 213, L 1000, r 17.288219174868797, S 6) --substeps 2 -t 2
    0x3e2f6e29bf880ee8ULL,  // random 294 (N 213, L 1000, r 17.288219174868797, S 6) --engine exact
    0xd6a8ca97f0028e28ULL,  // random 295 (N 332, L 100, r 1.3847488706773197, S 3) --broadphase brute -t 1
    0xd6a8ca97f0028e28ULL,  // random 295 (N 332, L 100, r 1.3847488706773197, S 3) --broadphase grid -t 2
    0xdd8fba5b39a7bb3eULL,  // random 295 (N 332, L 100, r 1.3847488706773197, S 3) --substeps 3 -t 2
    0xe7da8fe8e7bbf627ULL,  // random 295 (N 332, L 100, r 1.3847488706773197, S 3) --engine exact
    0x791f6c64d697ebe9ULL,  // random 296 (N 97, L 100, r 0.81012902903051121, S 3) --broadphase brute -t 1
    0x791f6c64d697ebe9ULL,  // random 296 (N 97, L 100, r 0.81012902903051121, S 3) --broadphase grid -t 1
    0x3d92b1eae782b5ecULL,  // random 296 (N 97, L 100, r 0.81012902903051121, S 3) --substeps 4 -t 2
    0x9a0bcd695c9327cfULL,  // random 296 (N 97, L 100, r 0.81012902903051121, S 3) --engine exact
    0x6f7bc31dc184ddc7ULL,  // random 297 (N 104, L 100, r 2.4741349933002641, S 3) --broadphase brute -t 1
    0x6f7bc31dc184ddc7ULL,  // random 297 (N 104, L 100, r 2.4741349933002641, S 3) --broadphase grid -t 2
    0xae692cbb6e25237dULL,  // random 297 (N 104, L 100, r 2.4741349933002641, S 3) --substeps 2 -t 2
    0xfece142bedc3edd7ULL,  // random 297 (N 104, L 100, r 2.4741349933002641, S 3) --engine exact
    0xa161b56313cff39cULL,  // random 298 (N 151, L 40, r 0.12986184940261347, S 6) --broadphase brute -t 1
    0xa161b56313cff39cULL,  // random 298 (N 151, L 40, r 0.12986184940261347, S 6) --broadphase grid -t 1
    0x24a6351343e34e67ULL,  // random 298 (N 151, L 40, r 0.12986184940261347, S 6) --substeps 3 -t 2
    0x3e6f0a021ebe5607ULL,  // random 298 (N 151, L 40, r 0.12986184940261347, S 6) --engine exact
    0x5c3310f93a11c2aaULL,  // random 299 (N 328, L 250, r 4.607466355855097, S 3) --broadphase brute -t 1
    0x5c3310f93a11c2aaULL,  // random 299 (N 328, L 250, r 4.607466355855097, S 3) --broadphase grid -t 2
    0x7f7f1137ee05ada4ULL,  // random 299 (N 328, L 250, r 4.607466355855097, S 3) --substeps 4 -t 2
    0xd24bef29c304e464ULL,  // random 299 (N 328, L 250, r 4.607466355855097, S 3) --engine exact
    0x33cd08632417706cULL,  // random 70000 sorted by position -t 1
    0x33cd08632417706cULL,  // random 70000 sorted by position -t 2
};
