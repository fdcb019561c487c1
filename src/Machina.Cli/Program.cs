// The machina command. Everything happens in CliApp; this file only connects the console, Ctrl+C and termination signals.
using System.Runtime.InteropServices;
using System.Text;
using Machina.Cli;

Console.OutputEncoding = new UTF8Encoding(encoderShouldEmitUTF8Identifier: false);
using var cancel = new CancellationTokenSource();
// The first Ctrl+C (or a termination request) stops the command cleanly; a second Ctrl+C ends the process at once.
void Stop(PosixSignalContext signal)
{
    if (!cancel.IsCancellationRequested)
    {
        signal.Cancel = true;
        cancel.Cancel();
    }
}
using PosixSignalRegistration interrupt = PosixSignalRegistration.Create(PosixSignal.SIGINT, Stop);
using PosixSignalRegistration terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM, Stop);
var context = new CliContext(Console.In, Console.Out, Console.Error, cancel.Token, isTerminal: !Console.IsOutputRedirected);
return await CliApp.RunAsync(args, context);
