// What the judge reads of the diagnosis: its one door into grading/diagnosis/.
// The diagnosis says why a check failed and never changes a point
// (docs/architecture.md, Where new work goes); it sits below the judge, so it
// reads no check, and the judge includes of it this header alone
// (tests/tools/test_layout.cpp checks both). What the judge takes from it:
//
//   lab_files.hpp       LabFiles, the part of a lab the diagnosis reads (the
//                       judge's LabData is one), and read_diagnosis_files
//   state_diff.hpp      the reference records, and state_difference, whose
//                       sentence the state check gives its points by;
//                       add_state_diff, under a checkpoint's failed check
//   starting_code.hpp   starting_code_sentence, said in place of guesses
//                       (say_starting_code); code_only, which the forbidden
//                       check searches too
//   image_words.hpp     describe_difference, under a failed image check
//   known_mistakes.hpp  the known mistakes' frames a failed frame is matched to
//   frame_guesses.hpp   say_frame_guesses, and the sentence of a frame that is
//                       another checkpoint's (checkpoint_match_sentence)
//
// The rooms above the judge (report/, release/, commands/, ...) include the
// diagnosis's headers directly: file isolation (file_isolation.hpp) runs from
// `course grade`, with the judge's verdict on a frame given to it.
#pragma once

#include "grading/diagnosis/frame_guesses.hpp"
#include "grading/diagnosis/image_words.hpp"
#include "grading/diagnosis/known_mistakes.hpp"
#include "grading/diagnosis/lab_files.hpp"
#include "grading/diagnosis/starting_code.hpp"
#include "grading/diagnosis/state_diff.hpp"
