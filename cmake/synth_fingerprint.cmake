cmake_minimum_required(VERSION 3.25)
# Run at build time (see CMakeLists.txt): writes OUT, a header defining
# SEGSLAM_SYNTH_FINGERPRINT, the SHA-256 of the SOURCES ('|' between them) that decide what a
# synthetic sequence looks like. Tests key their cache of rendered sequences by it, so a changed
# renderer never hands a test frames it did not render. OUT is rewritten only when it changes.
string(REPLACE "|" ";" SOURCES "${SOURCES}")
list(SORT SOURCES)
set(contents "")
foreach(source IN LISTS SOURCES)
  file(READ "${source}" text)
  string(APPEND contents "${source}\n${text}\n")
endforeach()
string(SHA256 hash "${contents}")
string(SUBSTRING "${hash}" 0 16 fingerprint)
set(header "#pragma once\n#define SEGSLAM_SYNTH_FINGERPRINT \"${fingerprint}\"\n")
set(previous "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" previous)
endif()
if(NOT previous STREQUAL header)
  file(WRITE "${OUT}" "${header}")
endif()
