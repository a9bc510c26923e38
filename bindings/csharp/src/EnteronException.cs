// SPDX-License-Identifier: Apache-2.0
using System;

namespace Enteron
{
    /// <summary>
    /// A call into libenteron failed. <see cref="Status"/> is the C status and
    /// <see cref="Exception.Message"/> the library's message for it (ent_last_error(), read
    /// on the failing thread at once), which names the bad input:
    /// "intestine.radius must be > 0, got -1". As in C, the failed call changed nothing.
    /// </summary>
    [Serializable]
    public sealed class EnteronException : Exception
    {
        /// <summary>The status the C function returned (never <see cref="Enteron.Status.Ok"/>).</summary>
        public Status Status { get; private set; }

        /// <summary>The C function that failed ("ent_scene_step").</summary>
        public string Function { get; private set; }

        internal EnteronException(Status status, string function, string message)
            : base(string.IsNullOrEmpty(message) ? Library.StatusString(status) : message)
        {
            Status = status;
            Function = function;
        }

        /// <summary>"EnteronException (invalid argument) in ent_scene_step: message", then the stack.</summary>
        public override string ToString()
        {
            return string.Format("Enteron.EnteronException ({0}) in {1}: {2}{3}{4}", Library.StatusString(Status),
                                 Function, Message, Environment.NewLine, StackTrace);
        }

        /// <summary>
        /// Throws for any status but Ok. Called right after the C call, on the same thread,
        /// so that ent_last_error is that call's message. <paramref name="function"/> is a
        /// literal: the success path allocates nothing.
        /// </summary>
        internal static void Check(Status status, string function)
        {
            if (status != Status.Ok) throw new EnteronException(status, function, Library.LastError);
        }
    }
}
