# Sourced by Allrun and Allclean: setSlabs N sets system/decomposeParDict's
# numberOfSubdomains and n to N slabs across (N 1 1), keeping its comments
# (foamDictionary -set would drop them)
setSlabs()
{
    sed -i -e "s/^numberOfSubdomains .*/numberOfSubdomains  $1;/" \
        -e "s/^\( *n  *\)(.*);/\1($1 1 1);/" system/decomposeParDict
    grep -q "^numberOfSubdomains  $1;" system/decomposeParDict \
        && grep -q "^ *n  *($1 1 1);" system/decomposeParDict || {
        echo "could not set $1 slabs in system/decomposeParDict" 1>&2
        return 1
    }
}
