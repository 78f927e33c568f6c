# ZS_SANITIZE=address,undefined builds our own targets (not third-party code) with sanitizers.
set(ZS_SANITIZE "" CACHE STRING "Comma-separated sanitizers for zeroset targets, e.g. address,undefined")

function(zs_sanitize target)
  if(ZS_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${ZS_SANITIZE} -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=${ZS_SANITIZE})
  endif()
endfunction()

# Every library or executable of ours goes through here: warnings + sanitizer in one place.
function(zs_target_defaults target)
  target_link_libraries(${target} PRIVATE zs_warnings)
  target_compile_features(${target} PUBLIC cxx_std_20)
  zs_sanitize(${target})
endfunction()
