# Sourced by CLI tests: sets D to the shared data directory ($FNAV_DATA_DIR,
# ../shared/data, /work/shared/data) or to an empty string when absent.
D=""
for cand in "${FNAV_DATA_DIR:-}" ../shared/data /work/shared/data; do
    if [ -n "$cand" ] && [ -d "$cand" ]; then D=$cand; break; fi
done
