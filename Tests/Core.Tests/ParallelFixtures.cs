using NUnit.Framework;

// dotnet only (this file is not under Assets/, so Unity's Test Runner, which runs EditMode tests one at a time on the
// main thread, never sees it): run test fixtures side by side, one per core. Each fixture writes only into its own
// TempFolder and restores any culture it sets on its own thread, so fixtures are independent.
[assembly: Parallelizable(ParallelScope.Fixtures)]
