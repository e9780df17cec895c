/**
 * @file hx_commands.h
 * @brief Entry points of the harness subcommands (one file each: cmd_*.c).
 *        Each takes the arguments after its name and returns an exit code
 *        (hx_cli.h).
 */
#ifndef HX_COMMANDS_H
#define HX_COMMANDS_H

int hx_cmd_info(int argc, char **argv);
int hx_cmd_convert(int argc, char **argv);
int hx_cmd_merge(int argc, char **argv);
int hx_cmd_replay(int argc, char **argv);
int hx_cmd_eval(int argc, char **argv);
int hx_cmd_allan(int argc, char **argv);
int hx_cmd_psd(int argc, char **argv);
int hx_cmd_sim(int argc, char **argv);
int hx_cmd_montecarlo(int argc, char **argv);
int hx_cmd_simgap(int argc, char **argv);
int hx_cmd_simgap_validate(int argc, char **argv);
int hx_cmd_live(int argc, char **argv);
int hx_cmd_stream(int argc, char **argv);

#endif /* HX_COMMANDS_H */
