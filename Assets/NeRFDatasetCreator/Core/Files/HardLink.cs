using System;
using System.IO;
using System.Runtime.InteropServices;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A hard link: a second name for the same file, so a linked export holds real files (it survives moving, copying
    /// to another machine and deleting the source) without taking their space twice. .NET Standard 2.1 has no API for
    /// it, so this calls the operating system: POSIX <c>link(2)</c> on Linux and macOS, <c>CreateHardLinkW</c> on
    /// Windows. Any failure — another volume (EXDEV), a file system without hard links (FAT, exFAT, some network
    /// shares), a missing entry point — is a false return, and the caller copies instead.
    /// </summary>
    public static class HardLink
    {
        /// <summary>Links <paramref name="link"/> (which must not exist) to <paramref name="existing"/>; false when the system cannot.</summary>
        public static bool TryCreate(string existing, string link)
        {
            try
            {
                if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows)) return CreateHardLinkW(link, existing, IntPtr.Zero);
                return PosixLink(existing, link) == 0;
            }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException || e is NotSupportedException)
            {
                return false;
            }
        }

        // int link(const char *oldpath, const char *newpath); strings are marshalled as UTF-8 on Unix.
        [DllImport("libc", EntryPoint = "link", SetLastError = true)]
        static extern int PosixLink(string oldpath, string newpath);

        // BOOL CreateHardLinkW(LPCWSTR lpFileName, LPCWSTR lpExistingFileName, LPSECURITY_ATTRIBUTES lpSecurityAttributes);
        [DllImport("kernel32.dll", CharSet = CharSet.Unicode, SetLastError = true)]
        [return: MarshalAs(UnmanagedType.Bool)]
        static extern bool CreateHardLinkW(string lpFileName, string lpExistingFileName, IntPtr lpSecurityAttributes);
    }
}
