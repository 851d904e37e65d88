using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The editor-wide state a capture changes, and the one place that puts it back: each change is recorded in a
    /// <see cref="StateRestorer"/> right after it is made, and <see cref="Restore"/> undoes them newest first, exactly
    /// once, whatever ended the capture (its end, a cancel, an error, Play mode, a script reload, quitting).
    /// Only one capture runs at a time (<see cref="ActiveCapture"/>), so no other run can have changed the same state
    /// in between, and the values saved here are the user's own.
    /// </summary>
    sealed class CaptureEditorState
    {
        readonly StateRestorer _restorer = new StateRestorer();

        /// <summary>
        /// Defers domain reloads (a script edit mid-capture) until the capture ends: a reload in the middle would
        /// orphan the preview scene and the render textures. The lock is a native counter
        /// (UnityCsReference 2022.3 Editor/Mono/EditorApplication.bindings.cs:152-158, 6000.0 :146-152); while it is
        /// held, Unity still compiles and shows its lock icon in the status bar (AppStatusBar.cs:197-205, 2022.3).
        /// </summary>
        public void LockReload()
        {
            EditorApplication.LockReloadAssemblies();
            _restorer.Changed("the script reload lock", EditorApplication.UnlockReloadAssemblies);
        }

        /// <summary>
        /// With asynchronous shader compilation the editor draws not-yet-compiled variants with a cyan placeholder,
        /// which the first views would record. ShaderUtil.allowAsyncCompilation is a public editor-wide property
        /// (UnityCsReference 2022.3 Editor/Mono/ShaderUtil.bindings.cs:257, 6000.0 :265).
        /// </summary>
        public void CompileShadersSynchronously()
        {
            var was = ShaderUtil.allowAsyncCompilation;
            ShaderUtil.allowAsyncCompilation = false;
            _restorer.Changed("asynchronous shader compilation (ShaderUtil.allowAsyncCompilation = " + was + ")",
                () => ShaderUtil.allowAsyncCompilation = was);
        }

        /// <summary>Puts everything back, newest first; a second call does nothing. Never throws.</summary>
        public void Restore()
        {
            foreach (var failure in _restorer.RestoreAll()) Debug.LogException(failure);
        }
    }
}
