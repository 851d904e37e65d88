using System.Globalization;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Progress of <c>"geometryPack": "everyStep"</c> at the end of a capture (review R4-6): each step is posed and read on
    /// the main thread, so the editor cannot repaint a Background Tasks item meanwhile; a progress bar is drawn instead,
    /// by <c>EditorUtility.DisplayProgressBar</c> / <c>ClearProgressBar</c> (native, UCR Editor/Mono/EditorUtility.bindings.cs:184,
    /// 189 on 2022.3.76f1; :186, 191 on 6000.0.78f1), in a foreground and a background capture alike. Batch mode has no
    /// window: a log line every two seconds.
    /// </summary>
    sealed class GeometryPackProgress
    {
        const string Title = "NeRF Dataset Creator: geometry of every time step";

        float _lastLog = Time.realtimeSinceStartup;
        bool _drawn;

        /// <summary>Core's (steps done, steps) callback; main thread.</summary>
        public void Report(int done, int total)
        {
            var text = string.Format(CultureInfo.InvariantCulture, "time step {0} of {1}", done, total);
            if (Application.isBatchMode)
            {
                if (Time.realtimeSinceStartup - _lastLog < 2 && done < total) return;
                _lastLog = Time.realtimeSinceStartup;
                Debug.Log("NeRF Dataset Creator: geometry pack: " + text);
                return;
            }
            _drawn = true;
            EditorUtility.DisplayProgressBar(Title, text, total > 0 ? (float)done / total : 0);
        }

        public void Close()
        {
            if (_drawn) EditorUtility.ClearProgressBar();
            _drawn = false;
        }
    }
}
