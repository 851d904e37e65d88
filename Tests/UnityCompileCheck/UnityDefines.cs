using System.Collections.Generic;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>The scripting defines Unity's editor sets when it compiles an editor assembly.</summary>
    static class UnityDefines
    {
        // Every minor line Unity has shipped, oldest first: UNITY_X_Y_OR_NEWER is set for each one up to the editor's.
        // 6000.0 was 2023.3 in beta: it defines UNITY_2023_3_OR_NEWER, as the ordering here gives.
        static readonly (int Major, int Minor)[] Lines =
        {
            (5, 3), (5, 4), (5, 5), (5, 6),
            (2017, 1), (2017, 2), (2017, 3), (2017, 4),
            (2018, 1), (2018, 2), (2018, 3), (2018, 4),
            (2019, 1), (2019, 2), (2019, 3), (2019, 4),
            (2020, 1), (2020, 2), (2020, 3),
            (2021, 1), (2021, 2), (2021, 3),
            (2022, 1), (2022, 2), (2022, 3),
            (2023, 1), (2023, 2), (2023, 3),
            (6000, 0), (6000, 1), (6000, 2), (6000, 3), (6000, 4), (6000, 5),
        };

        public static List<string> ForEditor(int major, int minor)
        {
            var defines = new List<string>
            {
                "UNITY_EDITOR", "UNITY_EDITOR_64", "UNITY_64", "PLATFORM_ARCH_64", "ENABLE_MONO",
                // Editor assemblies use the .NET Framework profile (Unity docs: .NET profile support).
                "NET_4_6", "NET_UNITY_4_8", "CSHARP_7_3_OR_NEWER",
                // Set in any project that has the Test Framework package, which the test asmdefs require.
                "UNITY_INCLUDE_TESTS",
                "UNITY_" + major, "UNITY_" + major + "_" + minor,
            };
            var key = Key(major, minor);
            foreach (var (lineMajor, lineMinor) in Lines)
                if (Key(lineMajor, lineMinor) <= key)
                    defines.Add("UNITY_" + lineMajor + "_" + lineMinor + "_OR_NEWER");
            return defines;
        }

        static int Key(int major, int minor) => major * 100 + minor;
    }
}
