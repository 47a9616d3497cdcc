# Fit-search tests the sanitized suite leaves out (scripts/test-sanitized.sh: ctest -LE heavy_fit),
# the plain suite runs them. Each spent a minute or more under ASan measuring sheets, and every
# call it makes is also made, under ASan, by a faster test (docs/performance.md, "CI time").
# Read by ctest after the discovered tests (tests/CMakeLists.txt); a name no build has is skipped.
set(curvefold_heavy_fit
  # chooseStart(target, "") is TheChoiceStopsMeasuringAtItsDeadline...'s `whole`, and
  # chooseStart(target, "cylinder") ASymmetryAskedForIsKeptByTheStart's first call: the same tube.
  StartSurface.ATiltedTubeStartsFromACylinderPlacedOnItsAxis
  # The third and fourth readings of parametersFromUnfolding (swept sines whose facets bend as a
  # crease does): the same fromUnfolding, facetBendBelowGap and largestBendBelow every reading of
  # a creased or smooth target runs (StartSurface.ACreasedTargetOfAnotherArea...,
  # ATubeOfOtherFacets..., ASymmetryAskedFor..., AConeOrASweptCurveOfOtherParameters...).
  StartSurface.ASweptCurveWhoseFacetsBendAsMuchAsACreaseStartsFromTheSheetItUnfoldsTo
  StartSurface.ASweptCurveWhoseFacetsBendUnderTheThresholdButMoreThanTheDefaultsIsRead
)
set_tests_properties(${curvefold_heavy_fit} PROPERTIES LABELS heavy_fit)
